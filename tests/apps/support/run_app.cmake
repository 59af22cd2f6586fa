# Driver of one app end-to-end test, run as `cmake -P` (proxyvis_app_test registers it).
#
# Removes CLEAN_DIR and every EXPECT_FILE / NO_FILE path, runs EXE with ARGS RUNS times (default
# 1), then checks that the last exit code is EXPECT_CODE, that stdout+stderr match OUTPUT_REGEX
# (if given), that every EXPECT_FILE was written and that no NO_FILE was. Last, it include()s
# APP_CHECKS (the app's own .cmake file) for checks of its own, with the output in `out` and
# `err` and the helper expect_json_keys.
separate_arguments(args NATIVE_COMMAND "${ARGS}")
if(NOT RUNS)
  set(RUNS 1)
endif()
if(CLEAN_DIR)
  file(REMOVE_RECURSE "${CLEAN_DIR}")
endif()
foreach(f IN LISTS EXPECT_FILE NO_FILE)
  file(REMOVE "${f}")
endforeach()
foreach(run RANGE 1 ${RUNS})
  execute_process(COMMAND "${EXE}" ${args} RESULT_VARIABLE code OUTPUT_VARIABLE out
    ERROR_VARIABLE err)
endforeach()
if(NOT code EQUAL EXPECT_CODE)
  message(FATAL_ERROR "exit code ${code}, expected ${EXPECT_CODE}\nstdout:\n${out}\nstderr:\n${err}")
endif()
if(OUTPUT_REGEX AND NOT "${out}${err}" MATCHES "${OUTPUT_REGEX}")
  message(FATAL_ERROR "output does not match '${OUTPUT_REGEX}'\nstdout:\n${out}\nstderr:\n${err}")
endif()
foreach(f IN LISTS EXPECT_FILE)
  if(NOT EXISTS "${f}")
    message(FATAL_ERROR "${f} was not written")
  endif()
endforeach()
foreach(f IN LISTS NO_FILE)
  if(EXISTS "${f}")
    message(FATAL_ERROR "${f} was written although the run failed")
  endif()
endforeach()
# For APP_CHECKS: fails unless the JSON text `json` has every member named after it; `what` says
# where the JSON came from.
function(expect_json_keys what json)
  foreach(key ${ARGN})
    string(JSON value ERROR_VARIABLE missing GET "${json}" ${key})
    if(missing)
      message(FATAL_ERROR "${what}: JSON key '${key}' missing: ${missing}\n${json}")
    endif()
  endforeach()
endfunction()

# For APP_CHECKS: fails unless the value at the keys ARGN of `json` is `expected` (as text).
function(expect_json_value what json expected)
  string(JSON value GET "${json}" ${ARGN})
  if(NOT value STREQUAL expected)
    message(FATAL_ERROR "${what}: ${ARGN} = '${value}', expected '${expected}'\n${json}")
  endif()
endfunction()

# For APP_CHECKS of `--json -` runs: fails unless stdout is one JSON value enclosed in `open` and
# `close` ("[" "]" or "{" "}") and nothing else, and stderr matches `err_regex` (the human report
# went there). Sets `json` in the caller.
function(expect_only_json_on_stdout open close err_regex)
  string(STRIP "${out}" text)
  string(JSON type ERROR_VARIABLE bad TYPE "${text}")
  string(LENGTH "${text}" n)
  set(first "")
  set(last "")
  if(n GREATER 0)
    string(SUBSTRING "${text}" 0 1 first)
    math(EXPR end "${n} - 1")
    string(SUBSTRING "${text}" ${end} 1 last)
  endif()
  if(bad OR NOT first STREQUAL open OR NOT last STREQUAL close)
    message(FATAL_ERROR "stdout is not only JSON: ${bad}\nstdout:\n${out}")
  endif()
  if(NOT err MATCHES "${err_regex}")
    message(FATAL_ERROR "the report text is not on stderr:\n${err}")
  endif()
  set(json "${text}" PARENT_SCOPE)
endfunction()

if(APP_CHECKS)
  include("${APP_CHECKS}")
endif()
