"""Files for the cases of cases_proxyux.cmake: a plain file that an output path tries to use as a
folder. The inputs are the bundled meshes and scenes (the dragon: a run that does real work takes
seconds, so a check made only after the work shows as a timeout).
"""
import pathlib


def build(out: pathlib.Path, data: pathlib.Path) -> None:
    d = out / "proxyux"
    d.mkdir()
    (d / "a_file").write_text("not a folder\n")
