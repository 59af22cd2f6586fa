#!/usr/bin/env bash
# Writes a 1,000,000-triangle mesh (ten copies of the bundled 100k-triangle dragon side by side,
# placed as glTF nodes by tests/js/place_copies.mjs and flattened by mesh-info) in every format
# loadMesh reads, then runs bench_mesh_load on them: OBJ, binary PLY, Draco .drc (16 bits), GLB
# plain (mesh-info --save), Draco-compressed (gltf-pipeline -d) and meshopt-compressed
# (gltf-transform meshopt). The npm tools are tests/js's (./setup.sh test installs them).
#   bench/mesh_load/prepare.sh [BUILD_DIR [OUT_DIR]] [--rounds N]
set -euo pipefail
cd "$(dirname "$0")/../.."
build=build out=out/bench_mesh_load
if [ $# -gt 0 ] && [ "${1#--}" = "$1" ]; then build=$1; shift; fi
if [ $# -gt 0 ] && [ "${1#--}" = "$1" ]; then out=$1; shift; fi
tools=tests/js/node_modules/.bin
info="$build/bin/mesh-info"
mkdir -p "$out"
if [ ! -f "$out/dragon1m.glb" ]; then
  "$info" data/dragon.drc --save "$out/dragon.glb" --quiet >/dev/null
  node tests/js/place_copies.mjs "$out/dragon.glb" "$out/copies.glb" 10
  "$info" "$out/copies.glb" --save "$out/dragon1m.glb" --quiet >/dev/null
fi
for ext in obj ply; do
  [ -f "$out/dragon1m.$ext" ] || "$info" "$out/dragon1m.glb" --save "$out/dragon1m.$ext" --quiet >/dev/null
done
[ -f "$out/dragon1m.drc" ] ||
  "$info" "$out/dragon1m.glb" --save "$out/dragon1m.drc" --draco-bits 16 --quiet >/dev/null
[ -f "$out/dragon1m_draco.glb" ] ||
  "$tools/gltf-pipeline" -i "$out/dragon1m.glb" -o "$out/dragon1m_draco.glb" -d >/dev/null
[ -f "$out/dragon1m_meshopt.glb" ] ||
  "$tools/gltf-transform" meshopt "$out/dragon1m.glb" "$out/dragon1m_meshopt.glb" >/dev/null
"$build/bin/bench_mesh_load" "$out/dragon1m.obj" "$out/dragon1m.ply" "$out/dragon1m.drc" \
  "$out/dragon1m.glb" "$out/dragon1m_draco.glb" "$out/dragon1m_meshopt.glb" "$@"
