# Mesh loaders (lib/mesh): files from corpus_loaders.py. Every case runs mesh-info and proxy-gen,
# which load through the same loadMesh: exit 2, one error line naming the file, nothing written.
set(L @CORPUS@/loaders)

# loaders_case(NAME FILE REGEX): the two programs on FILE; REGEX follows the file name.
function(loaders_case name file regex)
  bad_input_test(loaders_${name}_info mesh-info "${L}/${file}" REGEX "${file}: ${regex}"
    INPUTS ${L}/${file})
  bad_input_test(loaders_${name}_gen proxy-gen "${L}/${file} -o @OUT@/p.ply"
    REGEX "${file}: ${regex}" INPUTS ${L}/${file} OUTPUTS @OUT@/p.ply @OUT@/p.ply.sha256)
endfunction()

# A PLY element of 2^31-1 records without properties: OpenMesh reserved 12 GB for it.
loaders_case(no_properties no_properties.ply "header declares 2147483647 'vertex' elements with no properties")
loaders_case(long_list long_list.ply "file ends inside face 0; its list of 2000000000 items")
# Beyond float range and non-numbers: an Error naming the line, not uninitialised values or a
# silently shifted OBJ face.
loaders_case(coord_1e39_off coord_1e39.off "number beyond float range on line 4")
loaders_case(coord_1e39_obj coord_1e39.obj "number beyond float range on line 2")
loaders_case(coord_1e39_ply coord_1e39.ply "number beyond float range on line 11")
loaders_case(coord_nan_off coord_nan.off "not a number on line 4")
loaders_case(coord_nan_obj coord_nan.obj "not a number on line 3")
loaders_case(coord_nan_binary_ply coord_nan_binary.ply "vertex 2 has a NaN")
loaders_case(bad_vertex_line_obj bad_vertex_line.obj "not a number on line 2")
loaders_case(fraction_index_off fraction_index.off "face index '1.5' on line 6")
loaders_case(fraction_count_off fraction_count.off "face vertex count '3.5' on line 6")
loaders_case(exponent_index_ply exponent_index.ply "'1e5' on line 13 is not a valid int")
# Raw bytes of the file are not echoed (the driver checks the output is printable).
loaders_case(binary_name_ply binary_name.ply "header declares 3 v")
loaders_case(binary_token_obj binary_token.obj "not a number on line 2")
# Draco flips that decoded without complaint (one made every y -1.7e38 and crashed proxy-gen).
loaders_case(dragon_origin_flip dragon_origin_flip.drc "corrupt Draco position quantization")
loaders_case(dragon_value_flip dragon_value_flip.drc "Draco position 0 is out of its range")
loaders_case(dragon_range_flip dragon_range_flip.drc "corrupt Draco position quantization")
# A flip that decodes to another valid dragon: its sidecar catches it.
loaders_case(dragon_sidecar dragon_sidecar.drc "content does not match its .sha256 sidecar")
# Sidecars that are not sha256sum lines or not files: an Error naming the sidecar, no hang.
bad_input_test(loaders_bad_sidecar_info mesh-info "${L}/cube_bad_sidecar.off"
  REGEX "cube_bad_sidecar.off.sha256: not a sha256sum line" INPUTS ${L}/cube_bad_sidecar.off
  ${L}/cube_bad_sidecar.off.sha256)
bad_input_test(loaders_bad_sidecar_gen proxy-gen "${L}/cube_bad_sidecar.off -o @OUT@/p.ply"
  REGEX "cube_bad_sidecar.off.sha256: not a sha256sum line" INPUTS ${L}/cube_bad_sidecar.off
  ${L}/cube_bad_sidecar.off.sha256 OUTPUTS @OUT@/p.ply @OUT@/p.ply.sha256)
bad_input_test(loaders_fifo_sidecar_info mesh-info "${L}/cube_fifo_sidecar.off"
  REGEX "cube_fifo_sidecar.off.sha256: not a regular file" INPUTS ${L}/cube_fifo_sidecar.off
  TIMEOUT 20)
# Devices and FIFOs in the formats the basic cases leave out (Draco, OFF).
bad_input_test(loaders_dev_zero_drc mesh-info "${L}/dev_zero.drc" REGEX "dev_zero.drc: not a regular"
  TIMEOUT 20)
bad_input_test(loaders_dev_zero_off proxy-gen "${L}/dev_zero.off -o @OUT@/p.ply"
  REGEX "dev_zero.off: not a regular" OUTPUTS @OUT@/p.ply TIMEOUT 20)
bad_input_test(loaders_fifo_drc proxy-gen "${L}/fifo.drc -o @OUT@/p.ply"
  REGEX "fifo.drc: not a regular" OUTPUTS @OUT@/p.ply TIMEOUT 20)
bad_input_test(loaders_fifo_ply mesh-info "${L}/fifo.ply" REGEX "fifo.ply: not a regular" TIMEOUT 20)
# mesh-info --expect-sha256: a hash that does not match is exit 2 with one line.
bad_input_test(loaders_expect_sha256 mesh-info
  "--expect-sha256 0000000000000000000000000000000000000000000000000000000000000000 ${L}/cube.off"
  REGEX "cube.off: content does not match --expect-sha256; its sha256 is [0-9a-f]+, expected 0+"
  INPUTS ${L}/cube.off)
bad_input_test(loaders_expect_sha256_malformed mesh-info "--expect-sha256 12ab ${L}/cube.off"
  REGEX "expect-sha256.*64 hex digits" INPUTS ${L}/cube.off)
# glTF: broken containers, data outside its bounds, points, cycles, unsupported required
# extensions and URIs that leave the asset's folder.
loaders_case(gltf_truncated gltf_truncated.glb "GLB header length lies")
loaders_case(gltf_chunk_lies gltf_chunk_lies.glb "GLB chunk 0 length lies")
loaders_case(gltf_points gltf_points.glb "meshes\\[0\\].primitives\\[0\\] \\(mesh 'tetra'\\) draws points")
loaders_case(gltf_accessor_past_view gltf_accessor_past_view.glb "accessors\\[0\\].*reaches past its buffer view")
loaders_case(gltf_index_range gltf_index_range.glb "meshes\\[0\\].primitives\\[0\\].indices\\[5\\] is 77")
loaders_case(gltf_cycle gltf_cycle.glb "nodes\\[0\\] is reached twice")
loaders_case(gltf_required gltf_required.glb "extensionsRequired\\[0\\] 'KHR_materials_variants' is not supported")
loaders_case(gltf_escape gltf_asset/escape.gltf "buffers\\[0\\].uri '../gltf_outside.bin' leaves the asset's folder")
loaders_case(gltf_absolute gltf_asset/absolute.gltf "buffers\\[0\\].uri 'file://.*' leaves the asset's folder")
# glTF as a scene and glTF outputs: a file without emissive triangles has no light to render by;
# --gltf and --compress name what they write.
bad_input_test(loaders_gltf_scene_no_light render "${L}/gltf_no_light.glb -o @OUT@/x.exr"
  REGEX "gltf_no_light.glb: no lights; direct illumination needs emissive triangles"
  INPUTS ${L}/gltf_no_light.glb OUTPUTS @OUT@/x.exr)
bad_input_test(loaders_gltf_scene_output_ext proxy-gen
  "@DATA@/../scenes/dragon-plane.json --out-dir @OUT@/d --gltf @OUT@/scene.ply"
  REGEX "scene.ply: --gltf writes .glb or .gltf" OUTPUTS @OUT@/d @OUT@/scene.ply)
bad_input_test(loaders_compress_not_gltf mesh-info "@DATA@/bunny.off --save @OUT@/b.ply --compress draco"
  REGEX "b.ply: --compress draco needs a .gltf or .glb output" OUTPUTS @OUT@/b.ply)
