"""The small unique parks the out-of-core tests render: a fresh work folder and
scenes/make_unique_park.py run into WORK/park."""
import os
import shutil
import sys

from script_checks import run


def make_park(bin_dir, source, work, count, prototypes, proxies=True):
    """Empties `work`, makes a park of `count` `prototypes` copies in WORK/park (with proxies at
    ratio 0.01 from proxy-gen, or none) and returns its scene file."""
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    park = os.path.join(work, "park")
    args = [sys.executable, os.path.join(source, "scenes", "make_unique_park.py"), "--count",
            str(count), "--prototypes", prototypes, "--out", park,
            "--mesh-info", os.path.join(bin_dir, "mesh-info")]
    args += (["--ratio", "0.01", "--proxy-gen", os.path.join(bin_dir, "proxy-gen")] if proxies
             else ["--no-proxies"])
    run(args)
    return os.path.join(park, "unique-park.json")
