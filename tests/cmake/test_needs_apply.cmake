# Read by ctest after the GoogleTest binaries' discovered tests (TestNeeds.cmake): each test
# labelled with its suite's needs. A test name is "Suite.Name", or "Prefix/Suite.Name/N" for a
# parameterised one. Every suite is in the table (tests/CMakeLists.txt's `unlabelled` check
# lists any that is not).
foreach(binary ${trailray_test_binaries})
  foreach(test ${${binary}_TESTS})
    string(REGEX REPLACE "^([^/.]*/)?([^./]+)\\..*$" "\\2" suite "${test}")
    if(DEFINED trailray_needs_${suite})
      set_tests_properties("${test}" PROPERTIES LABELS "${trailray_needs_${suite}}")
    endif()
  endforeach()
endforeach()
