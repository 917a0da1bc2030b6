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
foreach(package geographiclib zlib libzip libpng1.6 libjpeg-turbo libwebp freetype imgui)
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
set(ZLIB_LIBRARY ZLIB::ZLIB CACHE STRING "" FORCE)  # what FindZLIB gives find_package(ZLIB) users
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


# --- libpng: its sources and the prebuilt configuration header it ships ---
set(png_root "${TRAILRAY_DEBIAN_SOURCES}/libpng1.6")
set(png_generated "${PROJECT_BINARY_DIR}/web-png")
file(MAKE_DIRECTORY "${png_generated}")
file(COPY_FILE "${png_root}/scripts/pnglibconf.h.prebuilt" "${png_generated}/pnglibconf.h" ONLY_IF_DIFFERENT)
add_library(web_png STATIC
  ${png_root}/png.c ${png_root}/pngerror.c ${png_root}/pngget.c ${png_root}/pngmem.c ${png_root}/pngpread.c
  ${png_root}/pngread.c ${png_root}/pngrio.c ${png_root}/pngrtran.c ${png_root}/pngrutil.c ${png_root}/pngset.c
  ${png_root}/pngtrans.c ${png_root}/pngwio.c ${png_root}/pngwrite.c ${png_root}/pngwtran.c ${png_root}/pngwutil.c)
target_include_directories(web_png SYSTEM PUBLIC "${png_root}" "${png_generated}")
target_link_libraries(web_png PUBLIC web_zlib)
target_compile_options(web_png PRIVATE ${third_party_flags})
add_library(PNG::PNG ALIAS web_png)

# --- libjpeg-turbo as a separate CMake build (its project defines targets and install rules that
# clash with libzip's when both are subprojects); only its static TurboJPEG library is used ---
include(ExternalProject)
set(jpeg_build "${PROJECT_BINARY_DIR}/libjpeg-turbo")
ExternalProject_Add(web_jpeg_project
  SOURCE_DIR "${TRAILRAY_DEBIAN_SOURCES}/libjpeg-turbo"
  BINARY_DIR "${jpeg_build}"
  CMAKE_ARGS -DCMAKE_TOOLCHAIN_FILE=${CMAKE_TOOLCHAIN_FILE} -DCMAKE_BUILD_TYPE=Release -DENABLE_SHARED=OFF
             -DWITH_SIMD=OFF -DWITH_TURBOJPEG=ON -DCMAKE_C_FLAGS=-w
             -DCMAKE_C_COMPILER_LAUNCHER=${CMAKE_C_COMPILER_LAUNCHER}
             # CMake's check_type_size misreads wasm32 object files (it finds size_t to be 7 bytes)
             -DHAVE_SIZE_T=TRUE -DSIZE_T=4 -DHAVE_UNSIGNED_LONG=TRUE -DUNSIGNED_LONG=4
  BUILD_COMMAND ${CMAKE_COMMAND} --build "${jpeg_build}" --target turbojpeg-static
  INSTALL_COMMAND ""
  BUILD_BYPRODUCTS "${jpeg_build}/libturbojpeg.a")
add_library(web_turbojpeg STATIC IMPORTED GLOBAL)
set_target_properties(web_turbojpeg PROPERTIES IMPORTED_LOCATION "${jpeg_build}/libturbojpeg.a"
                      INTERFACE_INCLUDE_DIRECTORIES "${TRAILRAY_DEBIAN_SOURCES}/libjpeg-turbo")
add_dependencies(web_turbojpeg web_jpeg_project)
add_library(PkgConfig::TURBOJPEG ALIAS web_turbojpeg)

# --- libwebp and FreeType, through their own CMake projects with the optional parts off ---
foreach(option WEBP_BUILD_ANIM_UTILS WEBP_BUILD_CWEBP WEBP_BUILD_DWEBP WEBP_BUILD_GIF2WEBP WEBP_BUILD_IMG2WEBP
               WEBP_BUILD_VWEBP WEBP_BUILD_WEBPINFO WEBP_BUILD_LIBWEBPMUX WEBP_BUILD_WEBPMUX WEBP_BUILD_EXTRAS
               WEBP_USE_THREAD WEBP_ENABLE_SIMD)
  set(${option} OFF CACHE BOOL "" FORCE)
endforeach()
add_subdirectory("${TRAILRAY_DEBIAN_SOURCES}/libwebp" "${PROJECT_BINARY_DIR}/libwebp" EXCLUDE_FROM_ALL SYSTEM)
add_library(web_webp INTERFACE)
target_link_libraries(web_webp INTERFACE webp)
target_include_directories(web_webp SYSTEM INTERFACE "${TRAILRAY_DEBIAN_SOURCES}/libwebp/src")
add_library(PkgConfig::WEBP ALIAS web_webp)

foreach(option FT_DISABLE_BZIP2 FT_DISABLE_PNG FT_DISABLE_HARFBUZZ FT_DISABLE_BROTLI)
  set(${option} ON CACHE BOOL "" FORCE)
endforeach()
# Our zlib, not the copy FreeType would otherwise compile in (the two clash at link time).
set(FT_DISABLE_ZLIB OFF CACHE BOOL "" FORCE)
set(FT_REQUIRE_ZLIB ON CACHE BOOL "" FORCE)
add_subdirectory("${TRAILRAY_DEBIAN_SOURCES}/freetype" "${PROJECT_BINARY_DIR}/freetype" EXCLUDE_FROM_ALL SYSTEM)
target_compile_options(freetype PRIVATE ${third_party_flags})
add_library(web_freetype INTERFACE)
target_link_libraries(web_freetype INTERFACE freetype)
add_library(PkgConfig::FREETYPE ALIAS web_freetype)

# --- toml++: header-only ---
file(COPY "/usr/include/toml++" DESTINATION "${web_include}")
add_library(web_tomlpp INTERFACE)
target_compile_definitions(web_tomlpp INTERFACE TOML_HEADER_ONLY=1)
add_library(PkgConfig::TOMLPP ALIAS web_tomlpp)

# --- WebGL 2 through Emscripten's OpenGL ES 3 and EGL; GLFW 3 on the page's canvas ---
add_library(web_gles INTERFACE)
target_link_options(web_gles INTERFACE -sMIN_WEBGL_VERSION=2 -sMAX_WEBGL_VERSION=2 -sFULL_ES3=1 -lEGL -lGL)
add_library(PkgConfig::EGL ALIAS web_gles)
add_library(PkgConfig::GLESV2 ALIAS web_gles)
add_library(web_glfw INTERFACE)
target_link_options(web_glfw INTERFACE -sUSE_GLFW=3)
add_library(PkgConfig::GLFW ALIAS web_glfw)

# --- Dear ImGui's core, from Debian's source package (the version of libimgui-dev) ---
set(imgui_root "${TRAILRAY_DEBIAN_SOURCES}/imgui")
add_library(web_imgui STATIC ${imgui_root}/imgui.cpp ${imgui_root}/imgui_draw.cpp ${imgui_root}/imgui_tables.cpp
                             ${imgui_root}/imgui_widgets.cpp)
target_compile_options(web_imgui PRIVATE ${third_party_flags})
# Included as <imgui.h> (native: /usr/include/imgui is on the path through pkg-config).
target_include_directories(web_imgui SYSTEM PUBLIC "${imgui_root}")
add_library(PkgConfig::IMGUI ALIAS web_imgui)
