#!/usr/bin/env python3
"""render --geometry-budget's memory against its bound, measured: a small unique park of dragon
copies (each its own file, no proxies: exact-batched needs none).

  out_of_core_memory.py BIN_DIR SOURCE_DIR WORK_DIR

The bound (docs/out_of_core.md, "Memory"): the render's peak RSS growth, plus the proxies
resident before it began, is at most budget + proxies + image + 10 %. This test computes the
bound itself from the budget it asks for (a share of the scene's measured in-core bytes) and the
image's per-pixel buffers (IMAGE_BYTES_PER_PIXEL), and compares it with the growth the kernel's
high-water mark (VmHWM) gave. The in-core render's peak is the kernel's ru_maxrss of that child
process, taken from outside (the out-of-core program resets its high-water mark, so its own
ru_maxrss covers only the time since the last reset: its peak_rss_bytes is the largest of them).

Checks:
  - at 50 % and 75 %, one batch for the frame: growth + proxies <= the bound, and the program's
    own within_rss_bound agrees; the out-of-core process peaks below the in-core render of the
    same scene;
  - at 64 spp and a budget of the largest mesh's load, the queue cap splits the frame into
    batches (capped_batches > 0), the growth stays within the bound, and the image still equals
    the in-core exact image bit for bit.
"""
import json
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "support"))
from image_diff import differing_pairs  # noqa: E402
from script_checks import fail, run  # noqa: E402
from unique_park import make_park  # noqa: E402

WIDTH, HEIGHT = 256, 192
# The frame's per-pixel buffers at up to 64 spp: shading point (44 bytes), sums (40), own-mesh
# answers (a 64-bit word), output RGB + visibility (16).
IMAGE_BYTES_PER_PIXEL = 44 + 40 + 8 + 16
MIB = float(1 << 20)


def peak_of(args):
    """Runs `args` in a child and returns its ru_maxrss in bytes."""
    pid = os.fork()
    if pid == 0:
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, 1)
        os.execv(args[0], args)
    _, status, usage = os.wait4(pid, 0)
    if os.waitstatus_to_exitcode(status) != 0:
        p = run(args)  # again, for its message
        fail(f"{' '.join(args)} failed: {p.stderr}")
    return usage.ru_maxrss * 1024


def main():
    bin_dir, source, work = sys.argv[1:4]
    render = os.path.join(bin_dir, "render")
    scene = make_park(bin_dir, source, work, 4, "dragon", proxies=False)
    size = ["--width", str(WIDTH), "--height", str(HEIGHT), "--seed", "7", "--threads", "2",
            "--quiet"]

    in_core_peak = peak_of([render, scene, *size, "--spp", "8", "-o",
                            os.path.join(work, "in-core.exr")])
    for share in (50, 75):
        out = os.path.join(work, f"ooc-{share}.exr")
        js = os.path.join(work, f"ooc-{share}.json")
        run([render, scene, *size, "--spp", "8", "--geometry-budget", f"{share}%",
             "--batch-passes", "0", "-o", out, "--json", js])
        r = json.load(open(js))
        peak = r["peak_rss_bytes"]
        budget = share / 100 * r["in_core_bytes"]
        if abs(r["geometry_budget_bytes"] - budget) > 1:
            fail(f"{share} %: budget {r['geometry_budget_bytes']}, expected {budget:.0f}")
        image = WIDTH * HEIGHT * IMAGE_BYTES_PER_PIXEL
        if r["image_bytes"] != image:
            fail(f"{share} %: image_bytes {r['image_bytes']}, expected {image}")
        bound = 1.10 * (budget + r["proxy_bytes"] + image)
        held = r["peak_rss_growth_bytes"] + r["proxy_bytes"]
        print(f"ok: {share} %: the render grew RSS by {r['peak_rss_growth_bytes'] / MIB:.1f} MiB "
              f"(+ proxies {r['proxy_bytes'] / MIB:.1f}) against budget {budget / MIB:.1f} + "
              f"image {image / MIB:.1f} + 10 % = {bound / MIB:.1f} MiB; process peak "
              f"{peak / MIB:.1f} MiB, in core {in_core_peak / MIB:.1f} MiB")
        if held > bound:
            fail(f"{share} %: {held / MIB:.1f} MiB over the bound {bound / MIB:.1f} MiB")
        if not r["within_rss_bound"] or abs(r["rss_bound_bytes"] - bound) > 2:
            fail(f"{share} %: the program's bound {r['rss_bound_bytes']} "
                 f"(within: {r['within_rss_bound']}) is not {bound:.0f}")
        if not peak < in_core_peak:
            fail(f"{share} %: out of core peaked at {peak / MIB:.1f} MiB, in core at "
                 f"{in_core_peak / MIB:.1f}")

    # Many passes at the smallest budget: the queue cap splits the frame; the image is still the
    # in-core one.
    p = run([render, scene, *size, "--spp", "64", "--geometry-budget", "1", "-o",
             os.path.join(work, "no.exr")], expect=2)
    largest = p.stderr.split("give at least ")[1].split(" bytes")[0]
    ref = os.path.join(work, "in-core-64.exr")
    run([render, scene, *size, "--spp", "64", "-o", ref])
    out = os.path.join(work, "ooc-64.exr")
    js = os.path.join(work, "ooc-64.json")
    run([render, scene, *size, "--spp", "64", "--geometry-budget", largest, "--batch-passes", "0",
         "-o", out, "--json", js])
    r = json.load(open(js))
    image = WIDTH * HEIGHT * IMAGE_BYTES_PER_PIXEL
    bound = 1.10 * (int(largest) + r["proxy_bytes"] + image)
    held = r["peak_rss_growth_bytes"] + r["proxy_bytes"]
    print(f"ok: 64 spp at {int(largest) / MIB:.1f} MiB: {r['batches']} batches "
          f"({r['capped_batches']} ended by the queue cap of {r['queue_cap_bytes'] / MIB:.2f} "
          f"MiB), growth {held / MIB:.1f} MiB against {bound / MIB:.1f} MiB")
    if r["capped_batches"] < 1 or r["batches"] < 2:
        fail(f"the queue cap split nothing: {r['batches']} batches")
    if held > bound:
        fail(f"64 spp: {held / MIB:.1f} MiB over the bound {bound / MIB:.1f} MiB")
    bad = differing_pairs([(ref, out)], channels="R,G,B")
    if bad:
        fail(f"the capped batches' image differs from the in-core one: {bad[0][2]}")
    print("ok: the capped batches' image equals the in-core one bit for bit")


if __name__ == "__main__":
    main()
