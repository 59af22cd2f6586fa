"""Mesh files as the scripts need them: their SHA-256 (a scene's proxies record it), their
vertices and triangles (OFF, OBJ, ASCII PLY: what proxy-gen writes and data/ holds), their
bounds."""
import hashlib


def sha256_file(path):
    """The file's SHA-256, hex (as sha256sum and a scene's "sha256" write it)."""
    h = hashlib.sha256()
    with open(path, "rb") as f:
        for chunk in iter(lambda: f.read(1 << 20), b""):
            h.update(chunk)
    return h.hexdigest()


def read_off(path):
    """(vertices as a flat list x0 y0 z0 x1 ..., triangles as a flat list of indices); polygons
    fan-triangulated."""
    with open(path) as f:
        lines = (l.split("#", 1)[0].split() for l in f)
        lines = [w for w in lines if w]
    if not lines[0][0].startswith("OFF"):
        raise ValueError(f"{path}: not an OFF file")
    head = lines[0][1:] or lines[1]
    first = 1 if lines[0][1:] else 2
    nv, nf = int(head[0]), int(head[1])
    verts = [float(t) for w in lines[first:first + nv] for t in w[:3]]
    faces = []
    for w in lines[first + nv:first + nv + nf]:
        n = int(w[0])
        idx = [int(t) for t in w[1:1 + n]]  # a colour after the indices is ignored
        for k in range(1, n - 1):
            faces.extend((idx[0], idx[k], idx[k + 1]))
    return verts, faces


def read_obj(path):
    """As read_off, for an OBJ (negative indices count from the end)."""
    verts, faces = [], []
    with open(path) as f:
        for line in f:
            if line.startswith("v "):
                verts.extend(float(t) for t in line.split()[1:4])
            elif line.startswith("f "):
                idx = []
                for t in line.split()[1:]:
                    i = int(t.split("/")[0])
                    idx.append(i - 1 if i > 0 else len(verts) // 3 + i)
                for k in range(1, len(idx) - 1):
                    faces.extend((idx[0], idx[k], idx[k + 1]))
    return verts, faces


def read_ascii_ply(path):
    """As read_off, for an ASCII PLY (the first three vertex properties are x, y, z)."""
    with open(path) as f:
        if f.readline().strip() != "ply" or "ascii" not in f.readline():
            raise ValueError(f"{path}: not an ASCII PLY")
        nv = nf = 0
        element = None
        for line in f:
            w = line.split()
            if w[0] == "element":
                element = w[1]
                if element == "vertex":
                    nv = int(w[2])
                elif element == "face":
                    nf = int(w[2])
            elif w[0] == "end_header":
                break
        verts = []
        for _ in range(nv):
            verts.extend(float(t) for t in f.readline().split()[:3])
        faces = []
        for _ in range(nf):
            w = [int(t) for t in f.readline().split()]
            for k in range(2, w[0]):
                faces.extend((w[1], w[k], w[k + 1]))
    return verts, faces


def read_mesh(path):
    """read_off, read_obj or read_ascii_ply by the file's extension."""
    readers = {".off": read_off, ".obj": read_obj, ".ply": read_ascii_ply}
    ext = path[path.rfind("."):].lower()
    if ext not in readers:
        raise ValueError(f"{path}: not an .off, .obj or ASCII .ply")
    return readers[ext](path)


def bounds(verts):
    """([min x, min y, min z], [max x, max y, max z]) of a flat vertex list."""
    return ([min(verts[a::3]) for a in range(3)], [max(verts[a::3]) for a in range(3)])
