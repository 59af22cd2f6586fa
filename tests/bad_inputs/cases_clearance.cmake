# The clearance and precision flags (docs/clearance.md): out of range, not a number, both at once,
# an unknown reading; each one line naming the flag, exit 2, no output.
bad_input_test(gen_clearance_negative proxy-gen "@DATA@/bunny.off --clearance -1 -o @OUT@/p.ply"
  REGEX "--clearance: must be in .0, [0-9.e+]+., got -1" TIMEOUT 20)
bad_input_test(gen_clearance_nan proxy-gen "@DATA@/bunny.off --clearance nan -o @OUT@/p.ply"
  REGEX "--clearance: expected a number, got 'nan'" TIMEOUT 20)
bad_input_test(gen_clearance_ulps_huge proxy-gen
  "@DATA@/bunny.off --clearance-ulps 1e9 -o @OUT@/p.ply" REGEX "--clearance-ulps: must be in"
  TIMEOUT 20)
bad_input_test(gen_clearance_both_ways proxy-gen
  "@DATA@/bunny.off --clearance 0.1 --clearance-ulps 2 -o @OUT@/p.ply"
  REGEX "--clearance excludes --clearance-ulps" TIMEOUT 20)
bad_input_test(check_precision_unknown proxy-check "@DATA@/bunny.off @DATA@/bunny.off --precision single"
  REGEX "--precision: single not in .float,double,both." TIMEOUT 20)
