# The WebAssembly build's libraries, under the same target names the native build gets from
# find_package, so that src/ and tests/ link them the same way on both platforms.
#
# Emscripten cannot use Debian's x86 libraries, and its "ports" download sources at build time
# (nothing may be downloaded here). So: header-only libraries are copied from the Debian -dev
# packages into the build tree (their folders under /usr/include cannot be include directories:
# /usr/include also holds glibc's headers, which must not mix with Emscripten's libc), and the
# compiled ones are built from Debian's source packages, unpacked by scripts/web-sources.sh.

enable_language(C)

# Every throw must be catchable (Emscripten's default turns a throw into an abort).
add_compile_options(-fexceptions)
add_link_options(-fexceptions -sALLOW_MEMORY_GROWTH=1 -sMAXIMUM_MEMORY=4GB)

set(TRAILRAY_DEBIAN_SOURCES "${PROJECT_SOURCE_DIR}/third_party/debian-src" CACHE PATH
    "Debian source packages for the WebAssembly build (scripts/web-sources.sh)")
foreach(package geographiclib zlib libzip)
  if(NOT EXISTS "${TRAILRAY_DEBIAN_SOURCES}/${package}/.unpacked")
    message(FATAL_ERROR "The WebAssembly build needs the source of ${package} in ${TRAILRAY_DEBIAN_SOURCES}: "
                        "run scripts/web-sources.sh (scripts/setup.sh does)")
  endif()
endforeach()

# --- header-only libraries, copied from /usr/include ---
set(web_include "${PROJECT_BINARY_DIR}/web-include")
foreach(dir fmt fast_float nlohmann glm GeographicLib)
  if(NOT EXISTS "/usr/include/${dir}")
    message(FATAL_ERROR "/usr/include/${dir} is missing: run scripts/setup.sh")
  endif()
  file(COPY "/usr/include/${dir}" DESTINATION "${web_include}")
endforeach()

add_library(fmt::fmt INTERFACE IMPORTED)
target_include_directories(fmt::fmt INTERFACE "${web_include}")
target_compile_definitions(fmt::fmt INTERFACE FMT_HEADER_ONLY=1)
add_library(nlohmann_json::nlohmann_json INTERFACE IMPORTED)
target_include_directories(nlohmann_json::nlohmann_json INTERFACE "${web_include}")
# fast_float and glm are found on the include path of every target (as /usr/include natively).
include_directories(SYSTEM "${web_include}")

# Warnings in other people's code are not ours to fix.
set(third_party_flags -w)

# --- GeographicLib: the classes geo/ and track/ use, and what they need ---
set(geographiclib_root "${TRAILRAY_DEBIAN_SOURCES}/geographiclib")
add_library(web_geographiclib STATIC
  ${geographiclib_root}/src/Geodesic.cpp ${geographiclib_root}/src/GeodesicLine.cpp
  ${geographiclib_root}/src/Geocentric.cpp ${geographiclib_root}/src/LocalCartesian.cpp
  ${geographiclib_root}/src/Math.cpp ${geographiclib_root}/src/Accumulator.cpp
  ${geographiclib_root}/src/Utility.cpp ${geographiclib_root}/src/DMS.cpp)
target_compile_options(web_geographiclib PRIVATE ${third_party_flags})
set(GeographicLib_LIBRARIES web_geographiclib)

# --- zlib ---
set(zlib_root "${TRAILRAY_DEBIAN_SOURCES}/zlib")
file(GLOB zlib_sources "${zlib_root}/*.c")
add_library(web_zlib STATIC ${zlib_sources})
target_include_directories(web_zlib PUBLIC "${zlib_root}")
target_compile_options(web_zlib PRIVATE ${third_party_flags})
target_compile_definitions(web_zlib PRIVATE HAVE_UNISTD_H=1)
# Imported (not an alias): libzip's export() of its own target then accepts the dependency.
add_library(ZLIB::ZLIB INTERFACE IMPORTED GLOBAL)
target_link_libraries(ZLIB::ZLIB INTERFACE web_zlib)

# --- libzip, through its own CMake project, with every optional codec and crypto off ---
set(ZLIB_INCLUDE_DIR "${zlib_root}" CACHE PATH "" FORCE)
set(ZLIB_LIBRARY web_zlib CACHE STRING "" FORCE)
foreach(option ENABLE_COMMONCRYPTO ENABLE_GNUTLS ENABLE_MBEDTLS ENABLE_OPENSSL ENABLE_WINDOWS_CRYPTO ENABLE_BZIP2
               ENABLE_LZMA ENABLE_ZSTD BUILD_TOOLS BUILD_REGRESS BUILD_EXAMPLES BUILD_DOC BUILD_SHARED_LIBS
               LIBZIP_DO_INSTALL)
  set(${option} OFF CACHE BOOL "" FORCE)
endforeach()
add_subdirectory("${TRAILRAY_DEBIAN_SOURCES}/libzip" "${PROJECT_BINARY_DIR}/libzip" EXCLUDE_FROM_ALL SYSTEM)
target_compile_options(zip PRIVATE ${third_party_flags})
add_library(web_libzip INTERFACE)
target_link_libraries(web_libzip INTERFACE zip)
add_library(PkgConfig::LIBZIP ALIAS web_libzip)

# --- GoogleTest, from Debian's googletest source package (/usr/src/googletest) ---
if(TRAILRAY_TESTS)
  set(gtest_root /usr/src/googletest/googletest)
  add_library(web_gtest STATIC ${gtest_root}/src/gtest-all.cc)
  target_include_directories(web_gtest SYSTEM PUBLIC ${gtest_root}/include PRIVATE ${gtest_root})
  target_compile_options(web_gtest PRIVATE ${third_party_flags})
  add_library(web_gtest_main STATIC ${gtest_root}/src/gtest_main.cc)
  target_link_libraries(web_gtest_main PUBLIC web_gtest)
  add_library(GTest::gtest ALIAS web_gtest)
  add_library(GTest::gtest_main ALIAS web_gtest_main)
endif()

