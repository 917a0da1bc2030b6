# One switch for ASan + UBSan over the whole build (project code and tests).
#
# The sanitizer tree is built at -O1 with line tables only: under ASan the suite's compute-heavy
# tests (brute-force references, the reference scorer) ran 5-10 times slower at -O0, and full
# debug information made the objects and the links several times larger; line tables are all a
# sanitizer report needs for file:line in its stacks. These options come after the build type's
# own (-O0 -g of Debug), so they win; NDEBUG stays unset, so assertions still fire.
if(TRAILRAY_SANITIZE)
  add_compile_options(-fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined -O1)
  if(CMAKE_CXX_COMPILER_ID MATCHES "Clang")
    add_compile_options(-gline-tables-only)
  else()
    add_compile_options(-g1)
  endif()
  add_link_options(-fsanitize=address,undefined)
endif()
