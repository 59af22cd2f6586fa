"""The scene JSON and its instance list (scenes/FORMAT.md): paths made absolute, so that a copy of
a scene can be written in any folder and still name the same files, and the instance list's
lines."""
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


def instance_lines(path):
    """The instance list's placements as (mesh name, [12 numbers of the row-major 3x4 matrix]);
    comments (#) and blank lines skipped."""
    out = []
    with open(path) as f:
        for line in f:
            words = line.split("#")[0].split()
            if words:
                out.append((words[0], [float(w) for w in words[1:]]))
    return out


def instance_counts(scene):
    """Placements per mesh name of a scene whose paths are absolute (load_scene_absolute): 1 for
    a placed mesh, plus one per line of the instance list."""
    counts = {m["name"]: int(m.get("place", True)) for m in scene["meshes"]}
    if scene.get("instances"):
        for name, _ in instance_lines(scene["instances"]["file"]):
            counts[name] = counts.get(name, 0) + 1
    return counts
