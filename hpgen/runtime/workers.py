"""The worker threads of the C backend's ensembles (hpgen.runtime.cbatch): one pool per
process, made at the first ensemble call on more than one thread and kept (a fresh pool per
call started its threads every call), grown when a call asks for more threads, made again
in a forked child (a fork copies no threads). A call on T threads runs T tasks that take
the call's slices in turn, so it never runs on more than T threads whatever the pool's size.
Standard library only.
"""
from __future__ import annotations

import os
import threading
from concurrent.futures import ThreadPoolExecutor
from typing import Callable, Sequence

_LOCK = threading.Lock()
_POOL: dict = {"pool": None, "pid": None, "size": 0}


def _pool(threads: int) -> ThreadPoolExecutor:
    """The process's pool, with at least ``threads`` workers."""
    with _LOCK:
        pool, pid = _POOL["pool"], os.getpid()
        if pool is None or _POOL["pid"] != pid or _POOL["size"] < threads:
            if pool is not None and _POOL["pid"] == pid:
                pool.shutdown(wait=False)            # its running tasks finish first
            pool = ThreadPoolExecutor(threads, thread_name_prefix="hpgen-ensemble")
            _POOL.update(pool=pool, pid=pid, size=threads)
        return pool


def run_slices(slices: Sequence, threads: int, run: Callable) -> None:
    """run(s) for every s of ``slices``, on ``threads`` threads of the pool (this thread
    waits), each taking the next slice when done with one; re-raises a slice's error (the
    other threads stop taking slices)."""
    if threads <= 1 or len(slices) <= 1:
        for s in slices:
            run(s)
        return
    it, lock = iter(slices), threading.Lock()
    failed: list[bool] = []

    def task():
        while not failed:
            with lock:
                s = next(it, None)
            if s is None:
                return
            try:
                run(s)
            except BaseException:
                failed.append(True)
                raise

    futures = [_pool(threads).submit(task) for _ in range(min(threads, len(slices)))]
    try:
        for f in futures:
            f.result()
    except BaseException:                 # (a Ctrl-C here: no further slice is started)
        failed.append(True)
        raise
