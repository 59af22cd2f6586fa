"""A small scene for proxy-gen's scene tests: bundled ecosys plants (instanced, not placed) on a
2-face ground that is too small to proxy, one quad light."""
import json
import pathlib
import shutil


def write_plant_scene(work: pathlib.Path, data: pathlib.Path, plants: dict, instances: str,
                      no_proxy=("flower2",)) -> pathlib.Path:
    """Writes work/scene.json with work/meshes/<name>.drc copied from data/ecosys/<file> for each
    name -> file of `plants`, the instance list `instances`, and "make_proxy": false on the meshes
    named in `no_proxy`. Returns the scene's path."""
    meshes = work / "meshes"
    meshes.mkdir()
    for name, file in plants.items():
        shutil.copyfile(data / "ecosys" / file, meshes / f"{name}.drc")
    (meshes / "ground.obj").write_text(
        "v -4 -4 0\nv 8 -4 0\nv 8 4 0\nv -4 4 0\nf 1 2 3\nf 1 3 4\n")
    (work / "plants.instances.txt").write_text(instances)
    scene = {
        "camera": {"eye": [1.2, -5, 1.6], "look_at": [1.2, 0.5, 0.3], "up": [0, 0, 1],
                   "fov_deg": 45, "resolution": [64, 48]},
        "lights": [{"type": "quad", "corner": [-2, -1, 6], "edge_u": [6, 0, 0],
                    "edge_v": [0, 3, 0], "radiance": [5, 5, 5]}],
        "meshes": [{"name": "ground", "file": "meshes/ground.obj"}] + [
            {"name": name, "file": f"meshes/{name}.drc", "place": False,
             **({"make_proxy": False} if name in no_proxy else {})} for name in plants],
        "instances": {"file": "plants.instances.txt"},
    }
    path = work / "scene.json"
    path.write_text(json.dumps(scene, indent=1))
    return path
