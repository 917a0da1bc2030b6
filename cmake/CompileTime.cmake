# What keeps the build quick on a 2-core machine (scripts/test.sh builds three trees from cold).
#
# Precompiled headers: every file of a target used to parse the same large third-party headers
# (GoogleTest, CLI11, nlohmann-json, fmt, GLM and the standard library) again, a third or more of
# its compile time. A target's precompiled header holds only headers from outside the project,
# so the layering rule (cmake/Layers.cmake) is untouched; each file still includes what it uses.
option(TRAILRAY_PCH "Precompile the heavy third-party headers of each target" ON)

set(trailray_pch_std <algorithm> <cmath> <cstdint> <memory> <optional> <string> <string_view> <vector>)

# trailray_precompile(<target> [header...]): the standard headers above and the given ones.
function(trailray_precompile target)
  if(TRAILRAY_PCH)
    target_precompile_headers(${target} PRIVATE ${trailray_pch_std} ${ARGN})
  endif()
endfunction()

# GCC 12 loses the system-header status of libstdc++ code that comes in through a precompiled
# header (CMake's `#pragma GCC system_header` in it does not help), so its known false positives
# inside char_traits.h on std::string copies (-Wstringop-overflow, -Wstringop-overread,
# -Warray-bounds: a dozen a build, at -O1 and above, that the plain build never showed) would
# fail -Werror. Those three are off there; AddressSanitizer checks such accesses as the tests
# run, and clang's tree keeps its own -Warray-bounds.
if(TRAILRAY_PCH AND CMAKE_CXX_COMPILER_ID STREQUAL "GNU" AND CMAKE_CXX_COMPILER_VERSION VERSION_LESS 13)
  add_compile_options(-Wno-stringop-overflow -Wno-stringop-overread -Wno-array-bounds)
endif()

# ccache caches files built with a precompiled header only when told what to ignore about it
# (scripts/compiler_cache.sh sets CCACHE_SLOPPINESS); clang must leave the file's time out of it.
if(TRAILRAY_PCH AND CMAKE_CXX_COMPILER_ID MATCHES "Clang")
  add_compile_options("$<$<COMPILE_LANGUAGE:CXX>:SHELL:-Xclang -fno-pch-timestamp>")
endif()

# trailray_test_code(<target>): test code (not the code under test) is optimised at -O1 in an
# optimised build: the libraries the tests exercise keep the build type's flags (-O3 in
# Release, as shipped), while the test files, a larger body of code than the libraries, compile
# in about half the time. The option comes after the build type's, so it wins.
# Emscripten optimises again at the link (wasm-opt at -O3 took 24 s for the track tests alone):
# -O1 there too.
function(trailray_test_code target)
  if(NOT CMAKE_BUILD_TYPE STREQUAL "Debug")
    target_compile_options(${target} PRIVATE -O1)
    if(EMSCRIPTEN)
      target_link_options(${target} PRIVATE -O1)
    endif()
  endif()
endfunction()
