# Warnings for project code only (third-party headers come in as SYSTEM).
function(trailray_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Wconversion
    -Wno-sign-conversion)
  # GCC 12 reports a false -Wrestrict inside libstdc++ for `"literal" + std::string` at -O2+
  # (GCC bug 105651, fixed in GCC 13); it names no project line, so it is switched off there.
  if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU" AND CMAKE_CXX_COMPILER_VERSION VERSION_LESS 13)
    target_compile_options(${target} PRIVATE -Wno-restrict)
  endif()
  if(TRAILRAY_WERROR)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
endfunction()
