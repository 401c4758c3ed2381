"""Checked reading of .npz files that a killed or damaged run may have left: a file is intact
when its zip directory and every member's local header read back and every member's CRC-32
matches its bytes (one full read; nothing is unpickled). Standard library only.
"""
from __future__ import annotations

import zipfile
from pathlib import Path


def is_intact(path) -> bool:
    """True when ``path`` is a zip file whose members all read back with their CRC-32."""
    try:
        with zipfile.ZipFile(Path(path)) as zf:
            return zf.testzip() is None
    except (OSError, ValueError, EOFError, zipfile.BadZipFile, zipfile.LargeZipFile):
        return False
