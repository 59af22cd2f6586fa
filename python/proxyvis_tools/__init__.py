"""The file formats the Python of scripts/ and bench/ shares, written once: scenes and instance
lists (scenes.py), meshes (meshes.py) and how a data-parallel job is started here (mpi.py).

Not to be confused with `proxyvis`, the compiled module of apps/python. Nothing edits sys.path to
find this package: its folder, python/ at the repository's root, is on PYTHONPATH. The tests set
it (ctest's environment, or the test's own helper); by hand, from the repository's root:

    PYTHONPATH=python python3 bench/data_parallel/bench_forwarding.py ...
"""
