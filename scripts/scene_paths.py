"""A scene JSON read with every file path made absolute, so that a copy of it can be written in
any folder and still name the same files."""
import json
import os


def load_scene_absolute(scene_path):
    """The scene at scene_path with its meshes', proxies' and instance list's paths absolute
    (a scene's paths are relative to its own file, scenes/FORMAT.md)."""
    base = os.path.dirname(os.path.abspath(scene_path))
    with open(scene_path) as f:
        scene = json.load(f)

    def absolute(path):
        return os.path.normpath(os.path.join(base, path))

    for m in scene["meshes"]:
        m["file"] = absolute(m["file"])
        for p in m.get("proxies", []):
            p["file"] = absolute(p["file"])
    if scene.get("instances"):
        scene["instances"]["file"] = absolute(scene["instances"]["file"])
    return scene
