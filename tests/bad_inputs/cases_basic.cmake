# Inputs that are not meshes at all.
bad_input_test(empty_off mesh-info "@CORPUS@/empty.off" INPUTS @CORPUS@/empty.off)
bad_input_test(unknown_format mesh-info "@CORPUS@/unknown.xyz" INPUTS @CORPUS@/unknown.xyz)
bad_input_test(directory_as_mesh proxy-gen "@CORPUS@/a_directory.ply -o @OUT@/p.ply"
  REGEX "a_directory.ply" OUTPUTS @OUT@/p.ply)
bad_input_test(dev_zero_is_refused mesh-info "@CORPUS@/dev_zero.ply" REGEX "dev_zero.ply.*regular"
  TIMEOUT 20)
bad_input_test(fifo_is_refused proxy-gen "@CORPUS@/fifo.obj -o @OUT@/p.ply"
  REGEX "fifo.obj.*regular" OUTPUTS @OUT@/p.ply TIMEOUT 20)
bad_input_test(empty_scene render-compare "@CORPUS@/empty.json --out @OUT@/r"
  INPUTS @CORPUS@/empty.json)
