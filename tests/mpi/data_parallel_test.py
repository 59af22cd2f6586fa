"""Data-parallel rendering over MPI, end to end (label mpi). Cases:
  identical  exact renders equal the single-process exact render bit for bit (R, G, B) at 1, 2, 3
             and 4 ranks, every forwarding policy, 1 and 2 threads, from render and render-compare
  files      no rank opens another rank's original (strace of every rank's open calls)
  faults     a rank that cannot read its original ends the job with exit 2 and one line naming the
             rank and the file; a rank killed mid-job fails the job; no output replaces a good one
  refuse     a proxy whose recorded class does not hold for its file is refused before rendering
  flags      every flag render and render-compare share with the single-process renderer acts
             on the data-parallel one (--proxy-kind, --build, --memory-budget, --width,
             --height, --q-min) or is refused with exit 2 and one error line
  roulette   roulette is unbiased: over seeds, its image minus the same seed's exact image has
             mean zero (z-test); with fixed costs it is the same image at 1 and 2 threads
  network    the alpha-beta fabric: emulated exact renders equal the single-process render at 2 and
             4 ranks, 1 and 2 threads; an emulated fabric of 20 ms per message makes the run wait
             at least its rounds' count exchanges; every row carries the fabric and the model;
             render-compare --emulate-network gives shared-memory and emulated rows side by side;
             unknown presets, bad figures and network flags without --data-parallel exit 2, and
             so do render-compare's --equal-time and --repeats, which the study does not do
  readme     the mpirun commands of README.md's data-parallel section run as written, in a
             folder laid out like a new clone, and the exact render equals `render`'s
  make_proxies  the test scene's proxies, made once into WORK_DIR/../proxies for the other cases
             and tests/slurm's data-parallel tests (a ctest fixture: none of them makes its own)
usage: data_parallel_test.py CASE RENDER_EXE PROXY_GEN_EXE DATA_DIR SCENES_DIR WORK_DIR"""
import os
import shutil
import sys
import types

sys.path.insert(0, os.path.dirname(__file__))
import dp_image_cases  # noqa: E402
import dp_input_cases  # noqa: E402
from mpi_support import make_unique_scene, mpirun_cmd, run  # noqa: E402

CASES = {"identical": dp_image_cases.identical, "roulette": dp_image_cases.roulette,
         "network": dp_image_cases.network, "files": dp_input_cases.files,
         "faults": dp_input_cases.faults, "refuse": dp_input_cases.refuse,
         "flags": dp_input_cases.flags, "readme": dp_input_cases.readme}


def main(case, render, proxy_gen, data_dir, scenes_dir, work):
    if case not in CASES and case != "make_proxies":
        sys.exit(f"unknown case {case}")
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    proxies = os.path.join(os.path.dirname(work), "proxies")
    # Roulette's 25 renders are mostly program start and scene load: its 2 x 2 grid of sculptures
    # (split over both ranks) loads in 0.7 s where the 3 x 3 grid takes 1.2 s.
    scene = (make_unique_scene(work, data_dir, scenes_dir, proxy_gen,
                               side=2 if case == "roulette" else 3, proxy_cache=proxies)
             if case != "readme" else None)
    if case == "make_proxies":
        print(f"ok: the test scene's proxies are in {proxies}")
        return

    def dp(ranks, out, *flags, expect=0, env=None):
        return run(mpirun_cmd(ranks) + [render, scene, "--data-parallel", "-o", out, "--quiet",
                                        *flags], expect=expect, env=env)

    CASES[case](types.SimpleNamespace(render=render, proxy_gen=proxy_gen, data_dir=data_dir,
                                      scenes_dir=scenes_dir, work=work, scene=scene, dp=dp))


if __name__ == "__main__":
    main(*sys.argv[1:7])
