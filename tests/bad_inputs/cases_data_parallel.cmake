# render and render-compare --data-parallel on bad flags and input, run as a one-rank MPI job
# (MPI's singleton start, no mpirun): exit code 2, one error line, nothing written. The
# multi-rank faults (a rank that cannot read its original, a killed rank, an unproved proxy) are
# in tests/mpi. Open MPI's own allocations are not ours to free: not run under the sanitizers.
set(rs @CORPUS@/render_scene.json)
set(dp_cases)
macro(dp_case name)
  bad_input_test(${name} ${ARGN})
  list(APPEND dp_cases bad_inputs.${name})
endmacro()
# dp_flags(NAME "FLAGS" REGEX): render --data-parallel FLAGS on the corpus's scene is refused.
macro(dp_flags name flags regex)
  bad_render_flags(${name} "--data-parallel ${flags}" "${regex}" TIMEOUT 30)
  list(APPEND dp_cases bad_inputs.${name})
endmacro()
dp_flags(dp_unknown_forwarding "--forwarding nearest" "--forwarding: unknown policy 'nearest'")
dp_flags(dp_estimator_not_available "--estimator culling" "--estimator culling is not available with --data-parallel")
dp_flags(dp_time_budget "--time 1" "--time is not available with --data-parallel")
dp_flags(dp_passes_per_round_zero "--passes-per-round 0" "--passes-per-round: must be in")
dp_flags(dp_forward_cost_negative "--forward-cost-us -3" "--forward-cost-us")
dp_flags(dp_proxy_kind_inside "--proxy-kind inside" "--proxy-kind inside")
dp_flags(dp_proxy_kind_general "--proxy-kind general" "--proxy-kind general")
dp_flags(dp_proxy_kind_without_proxies "--forwarding instance-boxes --proxy-kind outside"
  "--proxy-kind outside")
dp_flags(dp_probes "--probes 8" "--probes")
dp_flags(dp_roulette_costs "--roulette-costs 40,20,300,25,60" "--roulette-costs")
dp_flags(dp_network_unknown "--network infiniband" "--network infiniband is not a known fabric")
dp_flags(dp_network_alpha_negative "--network-alpha-us -1" "--network-alpha-us")
dp_flags(dp_network_beta_text "--network-beta-gbps fast" "--network-beta-gbps")
dp_flags(dp_network_unbatched_alpha "--network unbatched-20us --network-alpha-us 2"
  "has no alpha or beta to replace")
dp_flags(dp_network_shm_alpha_alone "--network-alpha-us 2" "needs --network-beta-gbps too")
dp_flags(dp_proxy_route_unknown "--proxy-route sometimes" "--proxy-route: unknown choice 'sometimes'")
dp_flags(dp_proxy_route_without_proxies "--forwarding instance-boxes --proxy-route always"
  "--proxy-route does not act without --forwarding proxies")
bad_render_flags(dp_proxy_route_alone "--proxy-route always" "--proxy-route needs --data-parallel"
  TIMEOUT 30)
dp_case(dp_compare_proxy_route_without_proxies render-compare
  "${rs} --data-parallel --forwarding domain-bounds,instance-boxes --proxy-route measured --out @OUT@/report"
  REGEX "--proxy-route does not act" OUTPUTS @OUT@/report TIMEOUT 30)
dp_case(dp_garbage_mesh render
  "@CORPUS@/render_garbage_mesh.json --data-parallel -o @OUT@/x.exr --json @OUT@/x.json"
  REGEX "render_garbage\\.obj" INPUTS @CORPUS@/render_garbage_mesh.json @CORPUS@/render_garbage.obj
  OUTPUTS @OUT@/x.exr @OUT@/x.json TIMEOUT 30)
dp_case(dp_output_is_scene render "${rs} --data-parallel -o ${rs}" REGEX "names the input"
  INPUTS ${rs} TIMEOUT 30)
dp_case(dp_compare_equal_time render-compare "${rs} --data-parallel --equal-time 2 --out @OUT@/report"
  REGEX "--equal-time is not available with --data-parallel" OUTPUTS @OUT@/report TIMEOUT 30)
dp_case(dp_compare_estimator render-compare
  "${rs} --data-parallel --estimators exact,paper-equal --out @OUT@/report"
  REGEX "--estimators paper-equal is not available" OUTPUTS @OUT@/report TIMEOUT 30)
dp_case(dp_compare_empty_forwarding render-compare
  "${rs} --data-parallel --forwarding , --out @OUT@/report"
  REGEX "--forwarding is empty" OUTPUTS @OUT@/report TIMEOUT 30)
dp_case(dp_compare_with_plan render-compare
  "${rs} --data-parallel --plan @OUT@/plan --out @OUT@/report"
  REGEX "--plan is not available with --data-parallel" OUTPUTS @OUT@/plan @OUT@/report TIMEOUT 30)
set_property(TEST ${dp_cases} APPEND PROPERTY LABELS not_sanitized mpi)
