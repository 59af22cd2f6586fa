"""Surfaces without an inside: proxy-gen --kind inside must refuse them (exit 2, one line naming
the file and what works instead), not build an inside proxy that no input could hold.

guarantee_theta.off: three triangle fans over one triangle loop; no boundary edge, but each loop
edge has three faces, so ray parity is undefined (before: the old check called it "not closed"
and advised --fill-holes, which cannot help).
"""
import pathlib

THETA_VERTICES = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0.3, 0.3, -1), (0.3, 0.3, 0.5), (0.3, 0.3, 1)]
THETA_FACES = [f for apex in (3, 4, 5) for f in ((0, 1, apex), (1, 2, apex), (2, 0, apex))]


def build(out: pathlib.Path, data: pathlib.Path) -> None:
    lines = ["OFF", f"{len(THETA_VERTICES)} {len(THETA_FACES)} 0"]
    lines += [" ".join(repr(float(c)) for c in v) for v in THETA_VERTICES]
    lines += ["3 " + " ".join(str(i) for i in f) for f in THETA_FACES]
    (out / "guarantee_theta.off").write_text("\n".join(lines) + "\n")
