"""bpy.ops.proxyvis.make_proxy, bpy.ops.proxyvis.check and bpy.ops.proxyvis.cancel."""
import bpy
import numpy as np
from bpy.props import EnumProperty, FloatProperty, IntProperty
from mathutils import Matrix

from . import backend as backends
from . import jobs, meshes

KINDS = [("outside", "Outside", "Contains the original: HM' = 0 (an occludee, a bounding volume)"),
         ("inside", "Inside", "Inside the original: MH' = 0 (an occluder)"),
         ("general", "General", "A simplified mesh with no guarantee (a level of detail)")]
METHODS = {"outside": ("wrap", "hull", "convex-parts"),
           "inside": ("wrap", "erode"),
           "general": ("qem", "cgal-sms", "meshopt")}
ALL_METHODS = [("DEFAULT", "Default", "proxy-gen's default for the kind (wrap; general: qem)")] + [
    (m, m, f"proxy-gen --method {m}")
    for m in ("wrap", "hull", "convex-parts", "erode", "qem", "cgal-sms", "meshopt")]


def typed(value):
    """The number a float property holds as the user typed it: Blender stores float32 (0.002
    becomes 0.0020000000949949), proxy-gen takes doubles; the shortest decimal that gives the
    same float32 is what was typed."""
    return float(str(np.float32(value)))


def preferences(context):
    addon = context.preferences.addons.get(__package__)
    return addon.preferences if addon else None


def resolve(context):
    return backends.resolve(preferences(context))


def report_messages(op, messages):
    for level, text in messages:
        op.report({level}, text)


class PROXYVIS_OT_make_proxy(bpy.types.Operator):
    """Make proxies of the selected objects (their evaluated, world-space triangles) with
    proxy-gen, check each with proxy-check and add it, parented, to "proxyvis proxies\""""
    bl_idname = "proxyvis.make_proxy"
    bl_label = "Make Proxies"
    # No REGISTER: no redo panel, whose changes would run the whole job again in the main thread.
    bl_options = {"UNDO"}

    kind: EnumProperty(name="Kind", items=KINDS, default="outside")
    method: EnumProperty(name="Method", items=ALL_METHODS, default="DEFAULT")
    max_faces: IntProperty(name="Max Faces", description="Face budget (0 = none)", min=0,
                           default=0)
    ratio: FloatProperty(name="Ratio", subtype="PERCENTAGE", min=0.0, max=100.0, default=0.0,
                         description="Face budget as a percentage of the input's faces, used "
                                     "when Max Faces is 0 (0 = proxy-gen's default)")
    offset: FloatProperty(name="Offset", min=0.0, max=1.0, default=0.0, precision=5,
                          description="wrap: offset as a fraction of the bounding-box diagonal "
                                      "(0 = proxy-gen's default, 1/600)")
    rays: IntProperty(name="Check Rays", min=1, default=100_000,
                      description="Segments proxy-check classifies against original and proxy")
    seed: IntProperty(name="Seed", min=0, default=0)
    threads: IntProperty(name="Threads", min=0, max=4096, default=0,
                         description="Worker threads (0 = all cores)")

    _timer = None
    _job = None

    @classmethod
    def poll(cls, context):
        return jobs.current is None or not jobs.current.alive()

    def settings(self):
        ratio = typed(self.ratio) / 100.0 if self.max_faces == 0 and self.ratio > 0 else 0.0
        return jobs.Settings(kind=self.kind,
                             method="" if self.method == "DEFAULT" else self.method,
                             max_faces=self.max_faces, ratio=ratio, offset=typed(self.offset),
                             rays=self.rays, seed=self.seed, threads=self.threads)

    def prepare(self, context):
        """(job, messages): the selected objects' triangles, read now in the main thread."""
        backend, notes = resolve(context)
        if backend is None:
            return None, [("ERROR", "no proxyvis backend: " + "; ".join(notes))]
        depsgraph = context.evaluated_depsgraph_get()
        items, messages = [], []
        for obj in sorted(context.selected_objects, key=lambda o: o.name):
            if obj.type not in meshes.GEOMETRY_TYPES:
                continue
            if meshes.is_proxy(obj):
                messages.append(("WARNING", f"{obj.name}: is a proxy; skipped"))
                continue
            V, F = meshes.world_triangles(obj, depsgraph)
            if len(F) == 0:
                messages.append(("ERROR", f"{obj.name}: has no faces"))
                continue
            items.append(jobs.Item(obj.name, V, F, meshes.source_sha256(V, F)))
        if not items:
            if not messages:
                messages.append(("ERROR", "select one or more mesh objects"))
            return None, messages
        return jobs.ProxyJob(backend, items, self.settings()), messages

    def execute(self, context):
        """From a script (and in background mode): the whole job now, in this thread."""
        job, messages = self.prepare(context)
        report_messages(self, messages)
        if job is None:
            return {"CANCELLED"}
        job.run()
        created, messages = job.finish(context)
        report_messages(self, messages)
        return {"FINISHED"} if created else {"CANCELLED"}

    def invoke(self, context, event):
        """From the panel: the job in a thread, followed by a timer; the panel shows progress."""
        if bpy.app.background or context.window is None:
            return self.execute(context)
        job, messages = self.prepare(context)
        report_messages(self, messages)
        if job is None:
            return {"CANCELLED"}
        jobs.current = self._job = job
        wm = context.window_manager
        wm.proxyvis_progress = 0.0
        wm.proxyvis_status = "starting"
        job.start()
        self._timer = wm.event_timer_add(0.1, window=context.window)
        wm.modal_handler_add(self)
        return {"RUNNING_MODAL"}

    def modal(self, context, event):
        job = self._job
        if event.type == "ESC" and event.value == "PRESS":
            job.cancel()
            return {"RUNNING_MODAL"}
        if event.type != "TIMER":
            return {"PASS_THROUGH"}
        wm = context.window_manager
        progress, status, seconds = job.snapshot()
        wm.proxyvis_progress = 100.0 * progress
        wm.proxyvis_status = f"{status}, {seconds:.0f} s" if job.alive() else status
        redraw(context)
        if job.alive():
            return {"PASS_THROUGH"}
        wm.event_timer_remove(self._timer)
        wm.proxyvis_progress = 0.0
        wm.proxyvis_status = ""
        jobs.current = None
        redraw(context)
        if job.cancelled:
            self.report({"INFO"}, "proxyvis: cancelled; no proxy was added")
            return {"CANCELLED"}
        created, messages = job.finish(context)
        report_messages(self, messages)
        return {"FINISHED"} if created else {"CANCELLED"}


    def cancel(self, context):
        """Blender ends the operator (a file loaded, the window closed): nothing is added."""
        self._job.cancel()
        context.window_manager.event_timer_remove(self._timer)
        jobs.current = None


def redraw(context):
    screen = context.screen
    if screen is None:
        return
    for area in screen.areas:
        if area.type == "VIEW_3D":
            area.tag_redraw()


class PROXYVIS_OT_cancel(bpy.types.Operator):
    """Cancel the running proxy job: no proxy of it is added (a running program is stopped; a
    running step of the module ends first)"""
    bl_idname = "proxyvis.cancel"
    bl_label = "Cancel"

    @classmethod
    def poll(cls, context):
        return jobs.current is not None and jobs.current.alive() and not jobs.current.cancelled

    def execute(self, context):
        jobs.current.cancel()
        return {"FINISHED"}


def _proxy_matrix(proxy):
    """The matrix that takes the proxy's vertices to world space: none (identity) while neither
    proxy nor original moved since it was made (its vertices are the world coordinates proxy-gen
    wrote, and the float product parent x parent inverse would round them), else its world
    matrix."""
    made = proxy.get(meshes.PREFIX + "parent_matrix")
    parent = proxy.parent
    if (made is not None and parent is not None and proxy.matrix_basis == Matrix.Identity(4)
            and list(made) == [x for row in parent.matrix_world for x in row]):
        return Matrix.Identity(4)
    return None


def proxies_of(objects):
    found = []
    for obj in objects:
        candidates = [obj] if meshes.is_proxy(obj) else [c for c in obj.children
                                                          if meshes.is_proxy(c)]
        for c in candidates:
            if c not in found:
                found.append(c)
    return found


class PROXYVIS_OT_check(bpy.types.Operator):
    """Classify the selected proxies (or the proxies of the selected originals) again against
    their parents with proxy-check; a proxy whose claimed class no longer holds turns red"""
    bl_idname = "proxyvis.check"
    bl_label = "Check"
    bl_options = {"REGISTER", "UNDO"}

    rays: IntProperty(name="Rays", min=1, default=100_000)
    seed: IntProperty(name="Seed", min=0, default=0)
    threads: IntProperty(name="Threads", min=0, max=4096, default=0)

    def execute(self, context):
        backend, notes = resolve(context)
        if backend is None:
            self.report({"ERROR"}, "no proxyvis backend: " + "; ".join(notes))
            return {"CANCELLED"}
        targets = proxies_of(context.selected_objects)
        if not targets:
            self.report({"ERROR"}, "select proxies (or their originals)")
            return {"CANCELLED"}
        depsgraph = context.evaluated_depsgraph_get()
        for proxy in targets:
            original = proxy.parent
            claim = proxy[meshes.PREFIX + "class"]
            if original is None:
                self.report({"ERROR"}, f"{proxy.name}: has no parent to check against")
                continue
            V, F = meshes.world_triangles(original, depsgraph)
            Vp, Fp = meshes.world_triangles(proxy, depsgraph, _proxy_matrix(proxy))
            changed = meshes.source_sha256(V, F) != proxy.get(meshes.PREFIX + "source_sha256")
            proxy[meshes.PREFIX + "source_changed"] = changed
            try:
                check = backend.check(V, F, Vp, Fp, self.rays, self.seed,
                                      claim if claim in ("outside", "inside") else None,
                                      self.threads, None)
            except backends.ProxyError as e:
                proxy[meshes.PREFIX + "check_class"] = "none"
                proxy[meshes.PREFIX + "check_holds"] = claim == "general"
                proxy[meshes.PREFIX + "check_error"] = e.message
                meshes.mark(proxy, claim == "general")
                self.report({"WARNING"}, f"{proxy.name}: {e.message}")
                continue
            if meshes.PREFIX + "check_error" in proxy.keys():
                del proxy[meshes.PREFIX + "check_error"]
            found = meshes.checked_class(check)
            holds = claim == "general" or (found == claim and check.get("ok", True))
            meshes.set_check_properties(proxy, check)
            proxy[meshes.PREFIX + "check_class"] = found
            proxy[meshes.PREFIX + "check_holds"] = holds
            meshes.mark(proxy, holds)
            counts = check.get("counts", {})
            text = (f"{proxy.name}: {found} (HM' {counts.get('HM')}, MH' {counts.get('MH')}"
                    f" of {check.get('rays')}); claims {claim}: "
                    + ("holds" if holds else "NO LONGER HOLDS"))
            if changed:
                text += "; the original changed since the proxy was made"
            self.report({"INFO" if holds else "WARNING"}, text)
        return {"FINISHED"}


classes = (PROXYVIS_OT_make_proxy, PROXYVIS_OT_cancel, PROXYVIS_OT_check)
