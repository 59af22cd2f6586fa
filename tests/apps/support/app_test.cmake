# Helpers shared by the app end-to-end tests in tests/apps/*.cmake (included before them).

set(PROXYVIS_APP_TEST_DRIVER ${CMAKE_CURRENT_LIST_DIR}/run_app.cmake)

# proxyvis_app_test(NAME TARGET CODE "ARGS" [REGEX r] [FILES paths...] [NO_FILES paths...]
#                   [RUNS n] [CLEAN dir] [CHECKS file] [DEFS -Dkey=value...] [TIMEOUT s])
# Registers test NAME: runs the app TARGET with ARGS (one string, split like a shell) through
# run_app.cmake, expecting exit code CODE; the options are that driver's checks. CHECKS is the
# app's .cmake file when it has checks of its own (in script mode), DEFS the variables they read
# (values without ';').
function(proxyvis_app_test name target code args)
  cmake_parse_arguments(T "" "REGEX;RUNS;CLEAN;CHECKS;TIMEOUT" "FILES;NO_FILES;DEFS" ${ARGN})
  set(defs -DEXE=$<TARGET_FILE:${target}> -DEXPECT_CODE=${code} "-DARGS=${args}" ${T_DEFS})
  foreach(v OUTPUT_REGEX:REGEX RUNS:RUNS CLEAN_DIR:CLEAN APP_CHECKS:CHECKS EXPECT_FILE:FILES
            NO_FILE:NO_FILES)
    string(REPLACE ":" ";" pair ${v})
    list(GET pair 0 def)
    list(GET pair 1 arg)
    if(T_${arg})
      string(REPLACE ";" "\\;" value "${T_${arg}}")  # a list stays one -D argument
      list(APPEND defs "-D${def}=${value}")
    endif()
  endforeach()
  add_test(NAME ${name} COMMAND ${CMAKE_COMMAND} ${defs} -P ${PROXYVIS_APP_TEST_DRIVER})
  if(T_TIMEOUT)
    set_tests_properties(${name} PROPERTIES TIMEOUT ${T_TIMEOUT})
  endif()
endfunction()

# proxyvis_python_test(NAME SCRIPT ARGS...): registers test NAME running the Python file SCRIPT
# of the calling file's folder with ARGS.
function(proxyvis_python_test name script)
  find_package(Python3 REQUIRED COMPONENTS Interpreter)
  add_test(NAME ${name} COMMAND ${Python3_EXECUTABLE} ${CMAKE_CURRENT_LIST_DIR}/${script} ${ARGN})
endfunction()

# Sets VAR to the test folder NAME in this build folder and creates it.
function(proxyvis_app_test_dir var name)
  set(${var} ${CMAKE_CURRENT_BINARY_DIR}/${name} PARENT_SCOPE)
  file(MAKE_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR}/${name})
endfunction()

# Writes the axis-aligned box [lo, hi]^3 to PATH as an OFF mesh of 12 outward triangles; FACES
# (default 12) keeps only the first ones (11 = a box with a hole).
function(proxyvis_write_box_off path lo hi)
  set(faces 12)
  if(ARGC GREATER 3)
    set(faces ${ARGV3})
  endif()
  set(text "OFF\n8 ${faces} 0\n")
  foreach(i RANGE 7)
    set(p "")
    foreach(bit 1 2 4)
      math(EXPR b "${i} & ${bit}")
      if(b)
        string(APPEND p "${hi} ")
      else()
        string(APPEND p "${lo} ")
      endif()
    endforeach()
    string(APPEND text "${p}\n")
  endforeach()
  set(tris "0 2 3" "0 3 1" "4 5 7" "4 7 6" "0 1 5" "0 5 4" "2 6 7" "2 7 3" "0 4 6" "0 6 2"
           "1 3 7" "1 7 5")
  list(SUBLIST tris 0 ${faces} tris)
  foreach(t ${tris})
    string(APPEND text "3 ${t}\n")
  endforeach()
  file(WRITE ${path} "${text}")
endfunction()
