#!/usr/bin/env python3
"""bench_cover against volumes known in closed form: a unit cube input, a proxy box twice its
volume around it (nothing uncovered, ratio 2) and two convex hulls that cover the lower half of
it and a quarter beside (half uncovered, ratio 0.5 inside the box). Estimates are compared with
the exact values within 5 standard errors.
  cover_test.py BENCH_COVER WORK_DIR"""
import json
import os
import subprocess
import sys


def box_off(lo, hi):
    (x0, y0, z0), (x1, y1, z1) = lo, hi
    v = [(x0, y0, z0), (x1, y0, z0), (x1, y1, z0), (x0, y1, z0),
         (x0, y0, z1), (x1, y0, z1), (x1, y1, z1), (x0, y1, z1)]
    quads = [(0, 3, 2, 1), (4, 5, 6, 7), (0, 1, 5, 4), (1, 2, 6, 5), (2, 3, 7, 6), (3, 0, 4, 7)]
    return v, [t for a, b, c, d in quads for t in ((a, b, c), (a, c, d))]


def write_off(path, box):
    v, f = box
    with open(path, "w") as out:
        out.write(f"OFF\n{len(v)} {len(f)} 0\n")
        out.writelines(f"{x} {y} {z}\n" for x, y, z in v)
        out.writelines(f"3 {a} {b} {c}\n" for a, b, c in f)


def write_hulls(path, boxes):
    with open(path, "w") as out:
        base = 1
        for i, (v, f) in enumerate(boxes):
            out.write(f"o hull_{i}\n")
            out.writelines(f"v {x} {y} {z}\n" for x, y, z in v)
            out.writelines(f"f {a + base} {b + base} {c + base}\n" for a, b, c in f)
            base += len(v)


def cover(tool, *args):
    p = subprocess.run([tool, *args, "--samples", "200000"], capture_output=True, text=True)
    assert p.returncode == 0, p.stderr
    return json.loads(p.stdout)


def near(value, exact, stderr, what):
    assert abs(value - exact) <= 5 * stderr + 1e-12, f"{what}: {value} vs {exact} (stderr {stderr})"


def main(tool, work):
    os.makedirs(work, exist_ok=True)
    cube, proxy, hulls = (os.path.join(work, n) for n in ("cube.off", "proxy.off", "hulls.obj"))
    write_off(cube, box_off((0, 0, 0), (1, 1, 1)))
    write_off(proxy, box_off((0, 0, 0), (2, 1, 1)))
    r = cover(tool, cube, "--solid", proxy)
    assert r["uncovered_samples"] == 0, r
    # Points are uniform in the box around both (volume 2): the ratio's error is binomial.
    p = 0.5
    near(r["volume_ratio"], 2.0, 2.0 * (p * (1 - p) / 200000) ** 0.5 / p, "proxy volume ratio")
    write_hulls(hulls, [box_off((0, 0, 0), (1, 1, 0.5)), box_off((1, 0, 0), (1.5, 1, 1))])
    r = cover(tool, cube, "--hulls", hulls)
    assert r["pieces"] == 2, r
    near(r["uncovered_share"], 0.5, r["uncovered_share_stderr"], "uncovered share")
    print("ok")


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2])
