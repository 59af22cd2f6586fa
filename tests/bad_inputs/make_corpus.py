#!/usr/bin/env python3
"""Writes the bad-input corpus: make_corpus.py OUT_DIR DATA_DIR.

Every corpus_*.py module beside this script contributes files through its build(out, data)
function (out and data are pathlib.Path). Files are written fresh on each run; nothing here is
random, so the corpus is the same on every machine.
"""
import importlib.util
import pathlib
import shutil
import sys


def main() -> int:
    out = pathlib.Path(sys.argv[1])
    data = pathlib.Path(sys.argv[2])
    if out.exists():
        shutil.rmtree(out)
    out.mkdir(parents=True)
    here = pathlib.Path(__file__).resolve().parent
    for module_path in sorted(here.glob("corpus_*.py")):
        spec = importlib.util.spec_from_file_location(module_path.stem, module_path)
        module = importlib.util.module_from_spec(spec)
        spec.loader.exec_module(module)
        module.build(out, data)
    print(f"bad-input corpus: {sum(1 for _ in out.rglob('*'))} files in {out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
