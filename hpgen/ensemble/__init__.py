"""Sweeps and ensembles: many members of one integrator on local threads or on Dask.

  members.py  the members' initial states and steps, checked; chunks
  chunk.py    one chunk through the C batch loops (local and on a worker alike)
  remote.py   the module's sources and content hash, installed and built on a worker
  sweep.py    hpgen.sweep: chunks over threads or Dask tasks, checkpoints, progress
  parts.py    the checkpoint of a sweep: its parts checked on load, the folder locked
  result.py   SweepResult: labelled member x time arrays, saved as .npz / .zarr / .nc
  grid.py     the grid file of ``hpgen sweep`` (YAML data, validated)
  cli.py      the ``hpgen sweep`` subcommand

Nothing here imports dask, xarray or zarr at import time: the local path needs numpy only.
"""
