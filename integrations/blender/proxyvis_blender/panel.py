"""The sidebar panel (View3D > Sidebar > proxyvis), its scene settings and the preferences."""
import bpy
from bpy.props import (BoolProperty, EnumProperty, FloatProperty, IntProperty, PointerProperty,
                       StringProperty)

from . import backend as backends
from . import jobs, meshes
from .operators import KINDS, METHODS, proxies_of, resolve

# EnumProperty items of the method, per kind (constant tuples: Blender keeps no reference to
# items a callback returns).
_METHOD_ITEMS = {kind: [("DEFAULT", "Default", f"proxy-gen's default for --kind {kind}: "
                         f"{methods[0]}")] + [(m, m, f"proxy-gen --method {m}") for m in methods]
                 for kind, methods in METHODS.items()}


def _method_items(self, context):
    return _METHOD_ITEMS[self.kind]


def _kind_changed(self, context):
    self.method = "DEFAULT"


class ProxyvisSettings(bpy.types.PropertyGroup):
    kind: EnumProperty(name="Kind", items=KINDS, default="outside", update=_kind_changed)
    method: EnumProperty(name="Method", items=_method_items)
    budget: EnumProperty(name="Budget", default="FACES",
                         items=[("FACES", "Faces", "At most this many faces"),
                                ("PERCENT", "%", "At most this percentage of the input's faces")])
    max_faces: IntProperty(name="Max Faces", min=4, default=500)
    ratio: FloatProperty(name="Ratio", subtype="PERCENTAGE", min=0.0001, max=100.0, default=2.0,
                         precision=2)
    offset: FloatProperty(name="Offset", min=0.0, max=1.0, default=0.0, precision=5, step=0.01,
                          description="wrap: offset as a fraction of the bounding-box diagonal "
                                      "(0 = proxy-gen's default, 1/600)")
    rays: IntProperty(name="Check Rays", min=1, default=100_000,
                      description="Segments proxy-check classifies against original and proxy")


def _prefs_changed(self, context):
    backends.forget()


class ProxyvisPreferences(bpy.types.AddonPreferences):
    bl_idname = __package__

    module_path: StringProperty(
        name="Module Path", subtype="DIR_PATH", update=_prefs_changed,
        description="Folder with the Python module proxyvis (empty: the build tree this add-on "
                    "was packaged in)")
    programs_folder: StringProperty(
        name="Programs Folder", subtype="DIR_PATH", update=_prefs_changed,
        description="Folder with proxy-gen and proxy-check, used when the module cannot be "
                    "imported (empty: the build tree's bin/, else PATH)")
    use_programs: BoolProperty(name="Always Use the Programs", default=False,
                               update=_prefs_changed)

    def draw(self, context):
        layout = self.layout
        layout.prop(self, "module_path")
        layout.label(text=f"empty: {backends.BUILD_MODULE_DIR or 'sys.path'}")
        layout.prop(self, "programs_folder")
        layout.label(text=f"empty: {backends.BUILD_PROGRAMS_DIR or 'PATH'}")
        layout.prop(self, "use_programs")
        layout.label(text="A module once imported stays until Blender restarts.")


def draw_backend(layout, context):
    backend, notes = resolve(context)
    box = layout.box()
    col = box.column(align=True)
    if backend is None:
        col.label(text="No backend: see the notes", icon="ERROR")
    elif backend.name == "module":
        col.label(text=f"Module proxyvis {backend.module.__version__}", icon="CHECKMARK")
    else:
        col.label(text="Programs (no module)", icon="CONSOLE")
    if backend is not None:
        col.label(text=backend.describe()[1])
    for note in notes:
        col.label(text=note, icon="INFO")


class PROXYVIS_PT_panel(bpy.types.Panel):
    bl_idname = "PROXYVIS_PT_panel"
    bl_label = "proxyvis proxies"
    bl_space_type = "VIEW_3D"
    bl_region_type = "UI"
    bl_category = "proxyvis"

    def draw(self, context):
        layout = self.layout
        s = context.scene.proxyvis
        wm = context.window_manager
        draw_backend(layout, context)

        layout.row().prop(s, "kind", expand=True)
        col = layout.column()
        col.use_property_split = True
        col.use_property_decorate = False
        col.prop(s, "method")
        col.row().prop(s, "budget", expand=True)
        if s.budget == "FACES":
            col.prop(s, "max_faces")
        else:
            col.prop(s, "ratio")
        if s.method in ("DEFAULT", "wrap") and s.kind in ("outside", "inside"):
            col.prop(s, "offset")
        col.prop(s, "rays")

        job = jobs.current
        if job is not None and job.alive():
            layout.label(text=wm.proxyvis_status or "starting", icon="TIME")
            row = layout.row(align=True)
            row.prop(wm, "proxyvis_progress", text="", slider=True)
            row.operator("proxyvis.cancel", text="Cancel", icon="CANCEL")
        else:
            n = sum(1 for o in context.selected_objects
                    if o.type in meshes.GEOMETRY_TYPES and not meshes.is_proxy(o))
            row = layout.row()
            row.scale_y = 1.4
            row.enabled = n > 0
            op = row.operator("proxyvis.make_proxy", icon="MOD_REMESH",
                              text=f"Make {s.kind.capitalize()} Prox{'y' if n == 1 else 'ies'}"
                                   + (f" ({n})" if n > 1 else ""))
            op.kind = s.kind
            op.method = s.method
            op.max_faces = s.max_faces if s.budget == "FACES" else 0
            op.ratio = s.ratio if s.budget == "PERCENT" else 0.0
            op.offset = s.offset
            op.rays = s.rays

        targets = proxies_of(context.selected_objects)
        row = layout.row()
        row.enabled = bool(targets)
        row.operator("proxyvis.check", icon="VIEWZOOM",
                     text="Check" + (f" ({len(targets)})" if len(targets) > 1 else ""))

        obj = context.active_object
        if obj is not None and meshes.is_proxy(obj):
            draw_proof(layout.box(), obj)


def draw_proof(box, obj):
    g = lambda key: obj.get(meshes.PREFIX + key)  # noqa: E731
    box.label(text=obj.name, icon="OBJECT_DATA")
    col = box.column(align=True)

    def line(name, value):
        split = col.split(factor=0.4)
        split.label(text=name)
        split.label(text=value)

    line("Class", f"{g('class')} ({g('method')})")
    line("Faces", f"{g('faces')}")
    if g("volume_ratio") is not None:
        line("Volume", f"\u00d7 {g('volume_ratio'):.4g}")
    if g("hausdorff_original_to_proxy") is not None:
        line("Hausdorff", f"{g('hausdorff_original_to_proxy'):.3g} / "
                          f"{g('hausdorff_proxy_to_original'):.3g}")
    if g("HM") is not None:
        line("HM'", f"{g('HM')} (\u2264 {g('HM_rate_upper_95'):.1e})")
        line("MH'", f"{g('MH')} (\u2264 {g('MH_rate_upper_95'):.1e})")
        line("Rays", f"{g('check_rays')}")
    holds = g("check_holds")
    if holds is not None:
        col.label(text=f"Check: {g('check_class')}, "
                       + ("holds" if holds else "BROKEN"),
                  icon="CHECKMARK" if holds else "ERROR")
    if g("check_error"):
        col.label(text=g("check_error"), icon="ERROR")


classes = (ProxyvisSettings, ProxyvisPreferences, PROXYVIS_PT_panel)


def register_properties():
    bpy.types.Scene.proxyvis = PointerProperty(type=ProxyvisSettings)
    bpy.types.WindowManager.proxyvis_progress = FloatProperty(
        name="Progress", subtype="PERCENTAGE", min=0.0, max=100.0, precision=0)
    bpy.types.WindowManager.proxyvis_status = StringProperty(name="Status")


def unregister_properties():
    del bpy.types.Scene.proxyvis
    del bpy.types.WindowManager.proxyvis_progress
    del bpy.types.WindowManager.proxyvis_status
