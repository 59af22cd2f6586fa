"""A proxy job: the selected objects' triangles, proxy-gen and proxy-check on each in turn, in a
Python thread (the module releases the GIL; the programs run as processes), then the proxy
objects, made in Blender's main thread only when every step is done and nothing was cancelled."""
import threading
import time
from dataclasses import dataclass

from . import backend as backends

# Share of one object's time spent making the proxy; the rest is the check's.
PROXY_SHARE = 0.9


@dataclass
class Settings:
    kind: str = "outside"
    method: str = ""  # "" = the program's default for the kind
    max_faces: int = 0  # 0 = none
    ratio: float = 0.0  # fraction of the input's faces; 0 = none
    offset: float = 0.0  # wrap: fraction of the diagonal; 0 = default
    rays: int = 100_000  # segments of the check
    seed: int = 0
    threads: int = 0  # 0 = all cores


@dataclass
class Item:
    name: str  # the original object's name
    V: object  # float32 n x 3, world space
    F: object  # int32 m x 3
    sha256: str


@dataclass
class Result:
    name: str
    Vp: object
    Fp: object
    report: dict
    check: dict
    sha256: str


class ProxyJob:
    def __init__(self, backend, items, settings):
        self.backend = backend
        self.items = items
        self.settings = settings
        self.results = []
        self.errors = []  # (object name, message, exit code)
        self.cancel_event = threading.Event()
        self.progress = 0.0
        self.status = "waiting"
        self.step_started = time.monotonic()
        self._thread = None
        self._lock = threading.Lock()

    # -- the work (worker thread, or inline in background mode) --------------------------------
    def _set(self, progress, status):
        with self._lock:
            if status != self.status:
                self.step_started = time.monotonic()
            self.progress, self.status = progress, status

    def run(self):
        s, n = self.settings, len(self.items)
        for i, item in enumerate(self.items):
            if self.cancel_event.is_set():
                return
            base = i / n

            def stage(fraction, what, base=base, item=item):
                self._set(base + PROXY_SHARE * fraction / n,
                          f"{item.name}: {what or 'proxy-gen'} ({i + 1}/{n})")

            stage(0.0, "proxy-gen")
            try:
                Vp, Fp, report = self.backend.proxy(item.V, item.F, s, self.cancel_event, stage)
                if self.cancel_event.is_set():
                    return
                self._set(base + PROXY_SHARE / n, f"{item.name}: proxy-check ({i + 1}/{n})")
                cls = report.get("class")
                check = self.backend.check(item.V, item.F, Vp, Fp, s.rays, s.seed,
                                           cls if cls in ("outside", "inside") else None,
                                           s.threads, self.cancel_event)
            except backends.Cancelled:
                return
            except backends.ProxyError as e:
                self.errors.append((item.name, e.message, e.exit_code))
                continue
            except Exception as e:  # noqa: BLE001  (a bug: say it, go on with the others)
                self.errors.append((item.name, f"{type(e).__name__}: {e}", 2))
                continue
            self.results.append(Result(item.name, Vp, Fp, report, check, item.sha256))
        self._set(1.0, "done")

    def start(self):
        self._thread = threading.Thread(target=self.run, name="proxyvis job", daemon=True)
        self._thread.start()

    def cancel(self):
        self.cancel_event.set()
        self._set(self.progress, "cancelling: the running step ends first")

    @property
    def cancelled(self):
        return self.cancel_event.is_set()

    def alive(self):
        return self._thread is not None and self._thread.is_alive()

    def wait(self, timeout=None):
        if self._thread is not None:
            self._thread.join(timeout)

    def snapshot(self):
        with self._lock:
            return self.progress, self.status, time.monotonic() - self.step_started

    # -- the results (Blender's main thread) ----------------------------------------------------
    def finish(self, context):
        """Creates the proxy objects (none when cancelled); returns (objects, messages)."""
        from . import meshes
        import bpy
        if self.cancelled:
            return [], []
        created, messages = [], []
        for r in self.results:
            original = bpy.data.objects.get(r.name)
            if original is None:
                messages.append(("WARNING", f"{r.name}: deleted meanwhile; its proxy is dropped"))
                continue
            obj = meshes.create_proxy(context, original, r.Vp, r.Fp, r.report, r.check,
                                      self.backend.name, r.sha256)
            created.append(obj)
            ratio = r.report.get("volume_ratio")
            messages.append(("INFO", f"{obj.name}: {obj['proxyvis_class']} / "
                             f"{r.report.get('method')}, {r.report.get('faces')} faces"
                             + (f", volume ratio {ratio:.4g}" if ratio is not None else "")))
        for name, message, _ in self.errors:
            messages.append(("ERROR", f"{name}: {message}"))
        return created, messages


# The job the panel shows (one at a time).
current = None
