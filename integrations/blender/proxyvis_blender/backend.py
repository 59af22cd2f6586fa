"""How the add-on reaches proxyvis: the Python module `proxyvis` (docs/python.md), or, when it
cannot be imported, the programs proxy-gen and proxy-check run on temporary binary PLY files.

Both take the same arrays (float32 world-space vertices, int32 triangles) and return the same
proxy and the same reports: a binary PLY stores float32 values, so the programs read exactly the
numbers the module is given (one reading, no text decimals).
"""
import json
import os
import shutil
import subprocess
import sys
import tempfile
import threading
import time

import numpy as np

try:  # written by CMake into the zip: this build's build/python and build/bin
    from . import _build_paths
    BUILD_MODULE_DIR = _build_paths.MODULE_DIR
    BUILD_PROGRAMS_DIR = _build_paths.PROGRAMS_DIR
except ImportError:  # the add-on run from the source tree
    BUILD_MODULE_DIR = ""
    BUILD_PROGRAMS_DIR = ""


class ProxyError(Exception):
    """A refusal or failure of proxy-gen / proxy-check: the text the programs print after
    "<program>: error: <file>: " and their exit code (1 a check failed, 2 bad input)."""

    def __init__(self, message, exit_code=2):
        super().__init__(message)
        self.message = message
        self.exit_code = exit_code


class Cancelled(Exception):
    """The job was cancelled while a program ran (the program was stopped)."""


def _strip(message, *prefixes):
    for p in prefixes:
        if message.startswith(p):
            return message[len(p):]
    return message


def _proxy_flags(s):
    """The settings as the module's keyword arguments (None = the program's default)."""
    return dict(kind=s.kind,
                method=s.method or None,
                max_faces=s.max_faces or None,
                ratio=s.ratio or None,
                offset=s.offset or None,
                seed=s.seed,
                threads=s.threads)


class ModuleBackend:
    name = "module"

    def __init__(self, module):
        self.module = module
        self.location = os.path.dirname(os.path.abspath(module.__file__))

    def describe(self):
        return f"Python module proxyvis {self.module.__version__}", self.location

    def proxy(self, V, F, settings, cancel, progress):
        kwargs = {k: v for k, v in _proxy_flags(settings).items() if v is not None}
        try:  # the module releases the GIL: Blender goes on meanwhile
            Vp, Fp, report = self.module.proxy(V, F, **kwargs)
        except self.module.Error as e:
            raise ProxyError(_strip(e.message, "V, F: "), e.exit_code) from None
        return np.asarray(Vp), np.asarray(Fp), report

    def check(self, V, F, Vp, Fp, rays, seed, expect, threads, cancel):
        try:
            return self.module.check(V, F, Vp, Fp, rays=rays, seed=seed, expect=expect,
                                     threads=threads)
        except self.module.Error as e:
            raise ProxyError(_strip(e.message, "V, F: ", "Vp, Fp: "), e.exit_code) from None


def write_ply(path, V, F):
    """A binary little-endian PLY of float32 vertices and int32 triangles (what the programs
    write and read exactly)."""
    V = np.ascontiguousarray(V, dtype="<f4").reshape(-1, 3)
    F = np.ascontiguousarray(F, dtype="<i4").reshape(-1, 3)
    faces = np.empty(len(F), dtype=[("n", "u1"), ("i", "<i4", (3,))])
    faces["n"] = 3
    faces["i"] = F
    header = ("ply\nformat binary_little_endian 1.0\n"
              f"element vertex {len(V)}\nproperty float x\nproperty float y\nproperty float z\n"
              f"element face {len(F)}\nproperty list uchar int vertex_indices\nend_header\n")
    with open(path, "wb") as f:
        f.write(header.encode("ascii"))
        f.write(V.tobytes())
        f.write(faces.tobytes())


_PLY_TYPES = {"char": "i1", "int8": "i1", "uchar": "u1", "uint8": "u1", "short": "i2",
              "int16": "i2", "ushort": "u2", "uint16": "u2", "int": "i4", "int32": "i4",
              "uint": "u4", "uint32": "u4", "float": "f4", "float32": "f4", "double": "f8",
              "float64": "f8"}


def read_ply(path):
    """The triangles of a binary little-endian PLY as proxy-gen writes it: (V float64, F int32)."""
    with open(path, "rb") as f:
        data = f.read()
    end = data.index(b"end_header\n") + len(b"end_header\n")
    lines = data[:end].decode("ascii").split("\n")
    if "format binary_little_endian 1.0" not in lines:
        raise ProxyError(f"{path}: not a binary little-endian PLY")
    elements, current = [], None
    for line in lines:
        words = line.split()
        if words[:1] == ["element"]:
            current = (words[1], int(words[2]), [])
            elements.append(current)
        elif words[:1] == ["property"] and current is not None:
            current[2].append(words[1:])
    V = F = None
    offset = end
    for name, count, props in elements:
        if name == "face":
            if len(props) != 1 or props[0][0] != "list":
                raise ProxyError(f"{path}: unexpected face properties {props}")
            dt = np.dtype([("n", "<" + _PLY_TYPES[props[0][1]]),
                           ("i", "<" + _PLY_TYPES[props[0][2]], (3,))])
            rec = np.frombuffer(data, dtype=dt, count=count, offset=offset)
            if count and np.any(rec["n"] != 3):
                raise ProxyError(f"{path}: a face is not a triangle")
            F = rec["i"].astype(np.int32)
        else:
            if any(p[0] == "list" for p in props):
                raise ProxyError(f"{path}: unexpected list property in element {name}")
            dt = np.dtype([(p[1], "<" + _PLY_TYPES[p[0]]) for p in props])
            rec = np.frombuffer(data, dtype=dt, count=count, offset=offset)
            if name == "vertex":
                V = np.stack([rec["x"], rec["y"], rec["z"]], axis=1).astype(np.float64)
        offset += dt.itemsize * count
    if V is None or F is None:
        raise ProxyError(f"{path}: no vertices or faces")
    return V, F


class ProgramBackend:
    name = "programs"

    def __init__(self, proxy_gen, proxy_check):
        self.proxy_gen = proxy_gen
        self.proxy_check = proxy_check

    def describe(self):
        return "programs proxy-gen and proxy-check", os.path.dirname(self.proxy_gen)

    def _run(self, program, args, cancel, progress):
        """Runs PROGRAM ARGS; stops it when `cancel` is set. Returns (exit code, error lines).
        proxy-gen's --progress lines ("proxy-gen [===>  ]  16.7%  0.0s validate") feed
        progress(fraction, stage)."""
        proc = subprocess.Popen([program, *args], stdout=subprocess.DEVNULL,
                                stderr=subprocess.PIPE, text=True)
        errors = []

        def read():
            for line in proc.stderr:
                line = line.rstrip("\n")
                if "%" in line and "] " in line and progress is not None:
                    try:
                        tail = line.split("] ", 1)[1].split()
                        progress(float(tail[0].rstrip("%")) / 100.0,
                                 " ".join(tail[2:]) if len(tail) > 2 else "")
                        continue
                    except (IndexError, ValueError):
                        pass
                errors.append(line)

        reader = threading.Thread(target=read, daemon=True)
        reader.start()
        while proc.poll() is None:
            if cancel is not None and cancel.is_set():
                proc.terminate()
                try:
                    proc.wait(5)
                except subprocess.TimeoutExpired:
                    proc.kill()
                    proc.wait()
                reader.join()
                raise Cancelled()
            time.sleep(0.05)
        reader.join()
        return proc.returncode, errors

    @staticmethod
    def _message(errors, program, *paths):
        prefix = f"{os.path.basename(program)}: error: "
        for line in reversed(errors):
            if line.startswith(prefix):
                return _strip(line[len(prefix):], *[p + ": " for p in paths])
        return "\n".join(errors[-5:]) or f"{os.path.basename(program)} failed"

    def proxy(self, V, F, settings, cancel, progress):
        with tempfile.TemporaryDirectory(prefix="proxyvis-blender-") as d:
            src, out, rep = (os.path.join(d, n) for n in ("input.ply", "proxy.ply", "proxy.json"))
            write_ply(src, V, F)
            args = [src, "-o", out, "--json", rep, "--progress"]
            for key, value in _proxy_flags(settings).items():
                if value is not None:
                    args += ["--" + key.replace("_", "-"), str(value)]
            code, errors = self._run(self.proxy_gen, args, cancel, progress)
            if code != 0:
                raise ProxyError(self._message(errors, self.proxy_gen, src), code)
            Vp, Fp = read_ply(out)
            with open(rep) as f:
                return Vp, Fp, json.load(f)

    def check(self, V, F, Vp, Fp, rays, seed, expect, threads, cancel):
        with tempfile.TemporaryDirectory(prefix="proxyvis-blender-") as d:
            a, b, rep = (os.path.join(d, n) for n in ("original.ply", "proxy.ply", "check.json"))
            write_ply(a, V, F)
            write_ply(b, Vp, Fp)
            args = [a, b, "--rays", str(rays), "--seed", str(seed), "--threads", str(threads),
                    "--json", rep, "-q"]
            if expect:
                args += ["--expect", expect]
            code, errors = self._run(self.proxy_check, args, cancel, None)
            # Exit 1 with a report: the evidence contradicts --expect ("ok": false), as the
            # module returns it.
            if code not in (0, 1) or not os.path.exists(rep):
                raise ProxyError(self._message(errors, self.proxy_check, a, b), code)
            with open(rep) as f:
                return json.load(f)


def module_dir(prefs):
    return (prefs.module_path if prefs and prefs.module_path else BUILD_MODULE_DIR) or ""


def programs_dir(prefs):
    return (prefs.programs_folder if prefs and prefs.programs_folder else BUILD_PROGRAMS_DIR) or ""


def _import_module(path):
    """The module proxyvis, from `path` put first on sys.path; (module, None) or (None, why)."""
    path = bpy_abspath(path)
    if path and path not in sys.path:
        sys.path.insert(0, path)
    try:
        import proxyvis  # noqa: F401  (numpy too: the module needs it)
        return proxyvis, None
    except ImportError as e:
        return None, str(e)


def _find_program(folder, name):
    folder = bpy_abspath(folder)
    if folder:
        p = os.path.join(folder, name)
        return p if os.path.isfile(p) and os.access(p, os.X_OK) else None
    return shutil.which(name)


def bpy_abspath(path):
    if not path:
        return ""
    try:
        import bpy
        path = bpy.path.abspath(path)
    except ImportError:
        pass
    return os.path.normpath(os.path.expanduser(path))


_cache = {}


def resolve(prefs):
    """(backend or None, notes): the module when it imports (unless the preference asks for the
    programs), else the programs when both are found. `notes` says why the module or the
    programs were not taken. Cached per setting."""
    key = (module_dir(prefs), programs_dir(prefs), bool(prefs and prefs.use_programs))
    if key not in _cache:
        notes = []
        if not key[2]:
            module, why = _import_module(key[0])
            if module is not None:
                _cache[key] = (ModuleBackend(module), notes)
                return _cache[key]
            notes.append(f"module not importable from '{key[0] or 'sys.path'}': {why}")
        else:
            notes.append("the preferences ask for the programs")
        gen, chk = _find_program(key[1], "proxy-gen"), _find_program(key[1], "proxy-check")
        if gen and chk:
            _cache[key] = (ProgramBackend(gen, chk), notes)
        else:
            notes.append(f"proxy-gen / proxy-check not found in '{key[1] or 'PATH'}'")
            _cache[key] = (None, notes)
    return _cache[key]


def forget():
    """Resolve again at the next use (after a preference changed)."""
    _cache.clear()
