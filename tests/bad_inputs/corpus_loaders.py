"""Mesh files the loaders must refuse (lib/mesh): lying headers, numbers OpenMesh misreads,
corrupted Draco files, sidecars that do not match or are not files, bytes that must not reach
the terminal. Everything is written into the "loaders" folder of the corpus."""
import hashlib
import json
import os
import pathlib
import struct

PLY_ASCII_HEADER = (
    "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
    "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
)


def flipped(data: bytes, from_end: int) -> bytes:
    """`data` with the byte `from_end` bytes before its end inverted."""
    b = bytearray(data)
    b[len(b) - from_end] ^= 0xFF
    return bytes(b)


def build(out: pathlib.Path, data: pathlib.Path) -> None:
    d = out / "loaders"
    d.mkdir()

    # 127 bytes declaring 2^31-1 vertices with no properties: OpenMesh reserved 12 GB for them.
    (d / "no_properties.ply").write_bytes(
        b"ply\nformat binary_little_endian 1.0\nelement vertex 2147483647\nelement face 1\n"
        b"property list uchar int vertex_indices\nend_header\n")

    # A binary list length of 2e9 in a 100-byte file: OpenMesh kept reading past the end.
    (d / "long_list.ply").write_bytes(
        PLY_ASCII_HEADER.replace("ascii", "binary_little_endian").replace("uchar", "int").encode()
        + bytes(36) + struct.pack("<i", 2000000000) + bytes(12))

    # Beyond float range: OpenMesh's stream failed and it used uninitialised values (OFF, PLY)
    # or dropped the vertex so that the face used the next one (OBJ).
    (d / "coord_1e39.off").write_text("OFF\n3 1 0\n0 0 0\n1e39 0 0\n0 1 0\n3 0 1 2\n")
    (d / "coord_1e39.obj").write_text(
        "v 0 0 0\nv 1e39 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\nf 1 3 4\n")
    (d / "coord_1e39.ply").write_text(PLY_ASCII_HEADER + "0 0 0\n1e39 0 0\n0 1 0\n3 0 1 2\n")
    (d / "coord_nan.off").write_text("OFF\n3 1 0\n0 0 0\nnan 0 0\n0 1 0\n3 0 1 2\n")
    (d / "coord_nan.obj").write_text("v 0 0 0\nv 1 0 0\nv 0 nan 0\nf 1 2 3\n")
    binary = PLY_ASCII_HEADER.replace("ascii", "binary_little_endian").encode()
    binary += struct.pack("<9f", 0, 0, 0, 1, 0, 0, 0, float("nan"), 0)
    binary += struct.pack("<B3i", 3, 0, 1, 2)
    (d / "coord_nan_binary.ply").write_bytes(binary)
    # A bad vertex line must not shift the later vertices (the face would change silently).
    (d / "bad_vertex_line.obj").write_text(
        "v 0 0 0\nv 1 x 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\nf 1 3 4\n")
    # Integers OpenMesh reads with operator>>: "1.5" split in two, "3.5" failed the stream.
    (d / "fraction_index.off").write_text("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 1.5\n")
    (d / "fraction_count.off").write_text("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3.5 0 1 2\n")
    (d / "exponent_index.ply").write_text(PLY_ASCII_HEADER + "0 0 0\n1 0 0\n0 1 0\n3 0 1 1e5\n")

    # Bytes that must not be echoed: an element name and a token with control and high bytes.
    (d / "binary_name.ply").write_bytes(
        b"ply\nformat ascii 1.0\nelement v\x01\xfe\x1b[31m 3\nproperty float x\nend_header\n")
    (d / "binary_token.obj").write_bytes(b"v 0 0 0\nv 1 \x1b]0;x\x07 0\nv 0 1 0\nf 1 2 3\n")

    # Single flipped bytes of the bundled dragon that Draco decoded without complaint: origin y
    # becomes -1.7e38 (every y the same; proxy-gen crashed), a quantized value beyond 16 bits, a
    # negative quantization range.
    dragon = (data / "dragon.drc").read_bytes()
    (d / "dragon_origin_flip.drc").write_bytes(flipped(dragon, 10))
    (d / "dragon_value_flip.drc").write_bytes(flipped(dragon, 19))
    (d / "dragon_range_flip.drc").write_bytes(flipped(dragon, 2))
    # A flip that decodes to another valid dragon (volume 155.7 -> 432.7): only a sidecar can
    # tell, so this copy carries the original's.
    (d / "dragon_sidecar.drc").write_bytes(flipped(dragon, 3))
    (d / "dragon_sidecar.drc.sha256").write_text(
        hashlib.sha256(dragon).hexdigest() + "  dragon_sidecar.drc\n")
    # The same flip without a sidecar loads (nothing in the format can tell): see docs.

    # Sidecars that are not sha256sum lines, or not files at all.
    cube = ("OFF\n8 12 0\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n0 0 1\n1 0 1\n0 1 1\n1 1 1\n"
            "3 0 2 3\n3 0 3 1\n3 4 5 7\n3 4 7 6\n3 0 1 5\n3 0 5 4\n3 2 6 7\n3 2 7 3\n"
            "3 0 4 6\n3 0 6 2\n3 1 3 7\n3 1 7 5\n")
    (d / "cube_bad_sidecar.off").write_text(cube)
    (d / "cube_bad_sidecar.off.sha256").write_bytes(b"\x00\xffnot a hash\n")
    (d / "cube_fifo_sidecar.off").write_text(cube)
    os.mkfifo(d / "cube_fifo_sidecar.off.sha256")  # reading it would block forever
    (d / "cube.off").write_text(cube)  # a good mesh for the --expect-sha256 case

    # Not regular files, in the formats the basic cases do not cover.
    os.symlink("/dev/zero", d / "dev_zero.drc")
    os.symlink("/dev/zero", d / "dev_zero.off")
    os.mkfifo(d / "fifo.drc")
    os.mkfifo(d / "fifo.ply")

    gltf_files(d)


def glb(doc: dict, bin_chunk: bytes) -> bytes:
    text = json.dumps(doc).encode()
    text += b" " * (-len(text) % 4)
    bin_chunk += b"\0" * (-len(bin_chunk) % 4)
    body = struct.pack("<II", len(text), 0x4E4F534A) + text
    body += struct.pack("<II", len(bin_chunk), 0x004E4942) + bin_chunk
    return struct.pack("<III", 0x46546C67, 2, 12 + len(body)) + body


def tetra_gltf(mode: int = 4) -> tuple:
    """A tetrahedron document (positions then uint32 indices in buffer 0) and its bytes."""
    positions = struct.pack("<12f", 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1)
    indices = struct.pack("<12I", 0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3)
    doc = {
        "asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
        "nodes": [{"mesh": 0}],
        "meshes": [{"name": "tetra", "primitives": [
            {"attributes": {"POSITION": 0}, "indices": 1, "mode": mode}]}],
        "buffers": [{"byteLength": 96}],
        "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 48},
                        {"buffer": 0, "byteOffset": 48, "byteLength": 48}],
        "accessors": [{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3"},
                      {"bufferView": 1, "componentType": 5125, "count": 12, "type": "SCALAR"}],
    }
    return doc, positions + indices


def gltf_files(d: pathlib.Path) -> None:
    """glTF and GLB files that must be refused: broken containers, data outside its bounds,
    graphs that are not trees, URIs that leave the asset's folder."""
    doc, data = tetra_gltf()
    good = glb(doc, data)
    (d / "gltf_truncated.glb").write_bytes(good[:-30])
    (d / "gltf_no_light.glb").write_bytes(good)  # a good mesh, but as a scene it has no light
    lying = bytearray(good)
    lying[12:16] = struct.pack("<I", 1 << 30)  # the JSON chunk claims 1 GB
    (d / "gltf_chunk_lies.glb").write_bytes(bytes(lying))
    (d / "gltf_points.glb").write_bytes(glb(tetra_gltf(mode=0)[0], data))
    past = json.loads(json.dumps(doc))
    past["accessors"][0]["count"] = 40000000  # 480 MB from a 48-byte view
    (d / "gltf_accessor_past_view.glb").write_bytes(glb(past, data))
    bad_index = bytearray(data)
    bad_index[48 + 4 * 5:48 + 4 * 6] = struct.pack("<I", 77)
    (d / "gltf_index_range.glb").write_bytes(glb(doc, bytes(bad_index)))
    cycle = json.loads(json.dumps(doc))
    cycle["nodes"] = [{"mesh": 0, "children": [1]}, {"children": [0]}]
    (d / "gltf_cycle.glb").write_bytes(glb(cycle, data))
    required = json.loads(json.dumps(doc))
    required["extensionsUsed"] = required["extensionsRequired"] = ["KHR_materials_variants"]
    (d / "gltf_required.glb").write_bytes(glb(required, data))
    # A .gltf whose buffer is a file beside the asset's folder (reached with ../).
    (d / "gltf_outside.bin").write_bytes(data)
    asset = d / "gltf_asset"
    asset.mkdir()
    escape = json.loads(json.dumps(doc))
    escape["buffers"][0]["uri"] = "../gltf_outside.bin"
    (asset / "escape.gltf").write_text(json.dumps(escape))
    absolute = json.loads(json.dumps(doc))
    absolute["buffers"][0]["uri"] = "file://" + str((d / "gltf_outside.bin").resolve())
    (asset / "absolute.gltf").write_text(json.dumps(absolute))
