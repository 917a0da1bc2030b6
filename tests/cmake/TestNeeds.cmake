# What each test needs to run, as ctest labels, read from its source when the tests are
# configured, so `ctest -L` / `-LE` choose tests by what a machine has:
#   gl       a GL context (EGL + Mesa), in the test's process or in a program it starts
#   window   an X display (the test starts Xvfb for the viewer's window)
#   browser  Chromium (tests/web)
#   data     ../shared/data (the test skips with a message when it is absent)
#   network  sockets on 127.0.0.1 (local tile and HTTP servers, `trailray serve`, Dask clusters)
#   python   /usr/bin/python3 with the module built (tests/python, peer scripts)
#   wasm     the WebAssembly build under node
#   cpu      none of those: the CPU alone
# A test may carry several. GoogleTest binaries hold many suites with different needs: their
# tests are discovered after the build (gtest_discover_tests), so the labels are given by suite
# name, from a table made here, by a script ctest reads after the discovered tests
# (test_needs_apply.cmake).

set(trailray_test_needs_dir ${CMAKE_CURRENT_LIST_DIR})  # inside the functions: the caller's

# The needs of one source file (C++ test or Python suite), by what it calls.
function(trailray_source_needs source binary out)
  file(READ ${source} text)
  # With the tests' own headers it includes (the helpers that start programs and servers).
  get_filename_component(dir ${source} DIRECTORY)
  string(REGEX MATCHALL "#include \"[^\"]+\.hpp\"" includes "${text}")
  foreach(include ${includes})
    string(REGEX REPLACE "#include \"([^\"]+)\"" "\\1" header "${include}")
    foreach(candidate ${dir}/${header} ${trailray_test_needs_dir}/../${header})
      if(EXISTS ${candidate})
        file(READ ${candidate} header_text)
        string(APPEND text "${header_text}")
        break()
      endif()
    endforeach()
  endforeach()
  set(needs "")
  if(binary STREQUAL "render_tests" OR text MATCHES "#include \"render/"
     OR text MATCHES "\" (render|video|view|bench)[ \"]" OR text MATCHES "trailray\\.render\\(|\\.render\\(")
    list(APPEND needs gl)
  endif()
  if(text MATCHES "xvfb")
    list(APPEND needs window)
  endif()
  if(text MATCHES "TRAILRAY_REQUIRE_DATA|shared_data\\(|SHARED_DATA|sharedData|shared_data|[^_a-z]shared\\(|shared_track_files")
    list(APPEND needs data)
  endif()
  if(text MATCHES "local_tile_server|serve_process|raw_http|127\\.0\\.0\\.1|localhost|LocalCluster|[\"'] ?serve[ \"']|--port")
    list(APPEND needs network)
  endif()
  if(text MATCHES "python3|Python3_EXECUTABLE|\\.py\"")
    list(APPEND needs python)
  endif()
  if(NOT needs)
    set(needs cpu)
  endif()
  set(${out} "${needs}" PARENT_SCOPE)
endfunction()

# Records the needs of every suite a GoogleTest binary's sources define (TEST, TEST_F, TEST_P),
# for test_needs_apply.cmake.
function(trailray_record_suite_needs binary)
  foreach(source ${ARGN})
    trailray_source_needs(${source} ${binary} needs)
    file(READ ${source} text)  # its own suites only
    string(REGEX MATCHALL "(TEST|TEST_F|TEST_P|TYPED_TEST)\\([ \n]*[A-Za-z0-9_]+," suites "${text}")
    foreach(suite ${suites})
      string(REGEX REPLACE ".*\\([ \n]*([A-Za-z0-9_]+),$" "\\1" suite "${suite}")
      get_property(known GLOBAL PROPERTY trailray_suite_needs_${suite})
      list(APPEND known ${needs})
      list(REMOVE_DUPLICATES known)
      if(known MATCHES "." AND NOT known STREQUAL "cpu")
        list(REMOVE_ITEM known cpu)
      endif()
      set_property(GLOBAL PROPERTY trailray_suite_needs_${suite} "${known}")
      set_property(GLOBAL APPEND PROPERTY trailray_suites ${suite})
    endforeach()
  endforeach()
  set_property(GLOBAL APPEND PROPERTY trailray_test_binaries ${binary})
endfunction()

# Writes the table and the script that applies it; call once, after every binary.
function(trailray_write_suite_needs)
  get_property(suites GLOBAL PROPERTY trailray_suites)
  get_property(binaries GLOBAL PROPERTY trailray_test_binaries)
  list(REMOVE_DUPLICATES suites)
  set(table "# Made by tests/cmake/TestNeeds.cmake: each GoogleTest suite's needs.\n")
  foreach(suite ${suites})
    get_property(needs GLOBAL PROPERTY trailray_suite_needs_${suite})
    string(APPEND table "set(trailray_needs_${suite} \"${needs}\")\n")
  endforeach()
  string(APPEND table "set(trailray_test_binaries \"${binaries}\")\n")
  file(WRITE ${CMAKE_CURRENT_BINARY_DIR}/test_needs_table.cmake "${table}")
  set_property(DIRECTORY APPEND PROPERTY TEST_INCLUDE_FILES ${CMAKE_CURRENT_BINARY_DIR}/test_needs_table.cmake
               ${trailray_test_needs_dir}/test_needs_apply.cmake)
endfunction()
