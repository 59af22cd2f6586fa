# proxy-gen's default stdout is the text summary (proxies/pipeline/proxy_report_text.h), not JSON: input
# and output with faces, the budget, the volume ratio, the Hausdorff distances with their unit,
# the verdict and class, and the stages in the order they run with total last.
#
# In script mode (run_app.cmake includes this file after its checks) it fails if stdout holds a
# JSON object (a raw dump) or if the stages are not exactly SUMMARY_STAGES (comma-separated), in order, total last.
if(CMAKE_SCRIPT_MODE_FILE)
  if(out MATCHES "[{}]")
    message(FATAL_ERROR "raw JSON in the summary:\n${out}")
  endif()
  string(REGEX MATCH "seconds:\n(.*)$" seconds "${out}")
  string(REGEX MATCHALL "\n  [a-z][a-z ]*[a-z]" labels "\n${CMAKE_MATCH_1}")
  list(TRANSFORM labels REPLACE "^\n  " "")
  string(REPLACE "," ";" expected "${SUMMARY_STAGES}")
  if(NOT labels STREQUAL expected)
    message(FATAL_ERROR "stages '${labels}', expected '${SUMMARY_STAGES}':\n${out}")
  endif()
  return()
endif()

set(ps_dir ${CMAKE_CURRENT_BINARY_DIR}/proxy_gen_summary)
proxyvis_app_test(proxy_gen_summary.mesh proxy-gen 0
  "${CMAKE_SOURCE_DIR}/data/bunny.off --kind outside --method hull --max-faces 100 -o ${ps_dir}/new/bunny.hull.ply"
  REGEX "^input: +[^\n]*bunny.off \\(6966 faces, closed\\)\noutput: +[^\n]*new/bunny.hull.ply\nproxy: +outside / hull, [0-9]+ faces \\([0-9]+ before the budget reduction\\)\nbudget: +100 faces \\(--max-faces\\), reached\nvolume ratio: 1\\.[0-9]+ \\(proxy volume / input volume\\)\nHausdorff \\(sampled, a lower bound\\): original->proxy [0-9.e-]+ \\([0-9.e-]+ % of the diagonal\\), proxy->original [0-9.e-]+ \\([0-9.e-]+ %\\), in scene units[^\n]*\nverified: +yes \\(exact containment check: [^\n]*\\)\nclass: +outside\nseconds:\n"
  CLEAN ${ps_dir} FILES ${ps_dir}/new/bunny.hull.ply TIMEOUT 120
  CHECKS ${CMAKE_CURRENT_LIST_FILE}
  DEFS "-DSUMMARY_STAGES=load,validate,build,budget reduction,verify,measure,total")
