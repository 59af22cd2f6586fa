"""proxyvis for Blender (docs/blender.md): outside, inside and general proxies of the selected
objects with their proof, made by the Python module proxyvis or the programs proxy-gen and
proxy-check; View3D > Sidebar > proxyvis."""
bl_info = {
    "name": "proxyvis proxies",
    "author": "proxyvis",
    "version": (0, 1, 0),
    "blender": (3, 4, 0),
    "location": "View3D > Sidebar > proxyvis",
    "description": "Outside, inside and general proxies of meshes, proved (proxy-gen) and "
                   "checked (proxy-check)",
    "doc_url": "",
    "category": "Object",
}

if "bpy" in locals():  # Reload Scripts
    import importlib
    for _m in (backend, meshes, jobs, operators, panel):  # noqa: F821
        importlib.reload(_m)
else:
    from . import backend, jobs, meshes, operators, panel

import bpy  # noqa: E402

_classes = operators.classes + panel.classes


def register():
    for cls in _classes:
        bpy.utils.register_class(cls)
    panel.register_properties()


def unregister():
    if jobs.current is not None:
        jobs.current.cancel()
        jobs.current = None
    panel.unregister_properties()
    for cls in reversed(_classes):
        bpy.utils.unregister_class(cls)
    backend.forget()
