#!/usr/bin/env python3
"""OpenImageIO is loaded only by processes that touch an image (lib/image/oiio_module.h):

- render and render-compare do not link it (no NEEDED entry naming OpenImageIO);
- render-compare's plan and its units never load it, the merge (which writes the report's
  images) does: seen through the dynamic loader's own log (LD_DEBUG=files);
- a program whose module is missing from its folder fails with exit 2, one error line naming the
  module's path, and no output; with the module beside it, it works when run by absolute path
  from another working directory;
- render writing an EXR (OpenEXR, lib/image/exr_io.h) never loads it and needs no module.

  oiio_module.py RENDER RENDER_COMPARE REPO_ROOT WORK_DIR
"""
import json
import os
import shutil
import subprocess
import sys


def check(cond, msg):
    if not cond:
        print("FAIL:", msg, file=sys.stderr)
        sys.exit(1)


def run(cmd, expect=0, env=None, cwd=None):
    r = subprocess.run(cmd, capture_output=True, text=True, env=env, cwd=cwd, timeout=300)
    check(r.returncode == expect,
          f"{' '.join(cmd)}: exit {r.returncode}, expected {expect}\n{r.stderr[-3000:]}")
    return r


def loaded_files(cmd):
    """The shared objects the dynamic loader opened while running cmd."""
    env = dict(os.environ, LD_DEBUG="files")
    r = run(cmd, env=env)
    return [line for line in r.stderr.splitlines() if "file=" in line]


def main():
    render, rc, repo, work = sys.argv[1:5]
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    scene = os.path.join(repo, "scenes", "cornell-bunny.json")
    module = os.path.join(os.path.dirname(rc), "libpv_oiio.so")
    check(os.path.isfile(module), f"{module}: not built beside {rc}")

    for exe in (render, rc):
        needed = run(["readelf", "-d", exe]).stdout
        check("NEEDED" in needed, f"{exe}: readelf shows no NEEDED entry:\n{needed}")
        check("OpenImageIO" not in needed, f"{exe} links OpenImageIO:\n{needed}")

    plan, out = os.path.join(work, "plan"), os.path.join(work, "report")
    flags = ["--width", "8", "--height", "8", "--seeds", "1", "--spp", "1", "--estimators",
             "exact", "--equal-time", "0", "--reference-spp", "1", "--threads", "1", "--quiet"]
    for name, cmd in (("plan", [rc, scene, *flags, "--out", out, "--plan", plan]),
                      ("unit 0", [rc, "--run-unit", plan, "0", "--quiet"])):
        files = loaded_files(cmd)
        check(files, f"{name}: LD_DEBUG=files logged nothing")
        oiio = [f for f in files if "OpenImageIO" in f or "libpv_oiio" in f]
        check(not oiio, f"{name} loaded OpenImageIO:\n" + "\n".join(oiio))
    with open(os.path.join(plan, "plan.json")) as f:
        units = json.load(f)["units"]
    for k in range(1, units):
        run([rc, "--run-unit", plan, str(k), "--quiet"])
    files = loaded_files([rc, "--merge", plan])
    check(any("libpv_oiio" in f for f in files), "the merge did not load the module")
    check(any("OpenImageIO" in f for f in files), "the merge did not load OpenImageIO")
    check(os.path.isfile(os.path.join(out, "report.html")), "the merge wrote no report")

    # A copy of render without its module: one error line naming the module, no image.
    bin_dir = os.path.join(work, "bin")
    os.makedirs(bin_dir)
    lone = os.path.join(bin_dir, "render")
    shutil.copy(render, lone)
    image = os.path.join(work, "out", "a.png")
    r = run([lone, scene, "--width", "8", "--height", "8", "--spp", "1", "-q", "-o", image],
            expect=2, cwd="/")
    lines = r.stderr.splitlines()
    expected = f"render: error: {os.path.join(bin_dir, 'libpv_oiio.so')}: cannot load the image module;"
    check(len(lines) == 1 and lines[0].startswith(expected),
          f"expected one line starting {expected!r}, got:\n{r.stderr}")
    check(not os.path.exists(image), f"{image} written without the module")
    check(not os.path.exists(os.path.dirname(image)) or not os.listdir(os.path.dirname(image)),
          "files left in the output folder")

    # An EXR needs no module: OpenEXR writes it, and OpenImageIO is never loaded.
    exr = os.path.join(work, "out", "a.exr")
    files = loaded_files([lone, scene, "--width", "8", "--height", "8", "--spp", "1", "-q",
                          "-o", exr])
    check(os.path.isfile(exr), f"{exr} not written without the module")
    oiio = [f for f in files if "OpenImageIO" in f or "libpv_oiio" in f]
    check(not oiio, "render -o a.exr loaded OpenImageIO:\n" + "\n".join(oiio))
    check(any("OpenEXR" in f for f in files), "render -o a.exr did not load OpenEXR")

    # With the module beside it, the copy works from another working directory.
    shutil.copy(module, bin_dir)
    run([lone, scene, "--width", "8", "--height", "8", "--spp", "1", "-q", "-o", image], cwd="/")
    check(os.path.isfile(image), f"{image} not written")
    print("oiio_module: ok")


if __name__ == "__main__":
    main()
