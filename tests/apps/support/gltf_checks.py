"""What the glTF app tests share: one ok/FAIL line per check, the failures kept for the exit code,
commands run with their output captured, and a GLB's JSON chunk."""
import json
import pathlib
import struct
import subprocess

FAILURES = []


def check(ok: bool, what: str) -> None:
    print(("ok   " if ok else "FAIL ") + what)
    if not ok:
        FAILURES.append(what)


def run(cmd, **kw) -> subprocess.CompletedProcess:
    return subprocess.run([str(c) for c in cmd], capture_output=True, text=True, **kw)


def glb_json(path: pathlib.Path) -> dict:
    data = path.read_bytes()
    length = struct.unpack("<I", data[12:16])[0]
    return json.loads(data[20:20 + length])
