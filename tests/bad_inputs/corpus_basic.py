"""Files every loader must refuse: empty, not a file, unknown format, endless or blocking."""
import os
import pathlib


def build(out: pathlib.Path, data: pathlib.Path) -> None:
    (out / "empty.off").write_bytes(b"")
    (out / "empty.json").write_bytes(b"")
    (out / "unknown.xyz").write_text("1 2 3\n")
    (out / "a_directory.ply").mkdir()
    os.symlink("/dev/zero", out / "dev_zero.ply")  # reading it never ends
    os.mkfifo(out / "fifo.obj")  # reading it blocks until a writer comes
