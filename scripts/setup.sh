#!/usr/bin/env bash
# Installs every Debian 12 package trailray needs to build, test and benchmark.
# This is the only place dependencies are listed; each line says why.
# Idempotent and non-interactive; uses sudo when not run as root.
set -euo pipefail

packages=(
  # --- build ---
  build-essential        # g++ 12 (C++20) and make
  cmake                  # the build (3.25)
  ninja-build            # fast incremental builds
  pkg-config             # locating libraries from CMake
  ccache                 # compiler cache (scripts/compiler_cache.sh): test.sh's four builds rebuilt from it in a fresh clone
  # --- libraries used by src/ ---
  libfast-float-dev      # correctly rounded number parsing, several times faster than strtod/from_chars
  zlib1g-dev             # reading .gpx.gz / .igc.gz / .tcx.gz transparently
  libzip-dev             # KMZ: the zip archives Google Earth packs KML in (track/io/zip_archive)
  libgeographiclib-dev   # WGS84 geodesic distances and local Cartesian frames (geo/)
  libcli11-dev           # command-line parsing (app/)
  libfmt-dev             # formatting of tables and messages
  nlohmann-json3-dev     # correct JSON output of `stats --json`
  libgdal-dev            # DEM rasters of any format and CRS, warped to Web Mercator tiles (terrain/)
  libcurl4-openssl-dev   # http(s) tile servers: parallel requests, timeouts, TLS (terrain/)
  libsqlite3-dev         # MBTiles files (terrain/)
  libpng-dev             # PNG height and imagery tiles, 8 and 16 bit (terrain/)
  libturbojpeg0-dev      # JPEG imagery tiles (terrain/)
  libheif-dev            # --photos: HEIC/HEIF photos decoded for their thumbnails (scene/pins/photo_decode)
  libwebp-dev            # WebP tiles (terrain/)
  libtomlplusplus-dev    # ~/.config/trailray/config.toml (terrain sources, cache size)
  libegl-dev             # EGL headers and libEGL (glvnd): headless GL contexts (render/)
  libgles-dev            # OpenGL ES 3 headers and libGLESv2 (glvnd): the renderer's one GL API
  libegl-mesa0           # Mesa's EGL driver: the surfaceless platform, rendering without a GPU or display
  libgl1-mesa-dri        # Mesa's drivers, llvmpipe among them: render tests and CI on the CPU
  glslang-tools          # glslangValidator: every shader is checked at build time, so an error fails the build
  libglm-dev             # GLSL-like vectors and matrices on the CPU (geo/ and up): ECEF points, camera, projections, sun direction
  libfreetype-dev        # the legend's text, rasterized on the CPU into the picture (render/legend)
  fonts-dejavu-core      # DejaVu Sans, embedded into the binary at build time for the legend
  libglfw3-dev           # the viewer's window: an OpenGL ES 3.0 context through EGL, input events (trailray view)
  libavcodec-dev         # `trailray video`: H.264 (libx264) and VP9 (libvpx) encoders
  libavformat-dev        # `trailray video`: MP4 (faststart) and WebM containers
  libswscale-dev         # `trailray video`: sRGB RGBA frames to BT.709 YUV 4:2:0
  libavutil-dev          # `trailray video`: frames, options, errors of the libraries above
  libmicrohttpd-dev      # `trailray serve`: HTTP with epoll, connection limits and timeouts, so slow clients stall nothing
  libimgui-dev           # Dear ImGui for the viewer's panels (its GLFW and OpenGL3 backends ship as sources)
  libexiv2-dev           # --photos: the photos' EXIF (GPS position, time, offset), JPEG and HEIC/HEIF (track/photos/exif_reader)
  libosmium2-dev         # --places: OpenStreetMap .osm.pbf/.osm(.gz/.bz2) read streaming (track/places; header-only)
  libprotozero-dev       # libosmium's protocol buffer decoder for .osm.pbf (header-only)
  libexpat1-dev          # libosmium's .osm XML parser
  libbz2-dev             # libosmium's .osm.bz2 input
  liblz4-dev             # libosmium's PBF blobs compressed with LZ4
  # --- the Python module (src/python/: `import trailray` for /usr/bin/python3) ---
  pybind11-dev           # C++ bindings with NumPy arrays over the track model's memory
  python3-dev            # Python.h and the extension suffix of Debian's python3
  python3-numpy          # the module's arrays
  python3-pytest         # the module's tests (ctest runs them)
  python3-pandas         # Track.to_pandas() and examples/python (optional for users)
  python3-dask           # trailray.dask: heatmaps and per-file work over a cluster (optional for users)
  python3-distributed    # trailray.dask's Client and the tests' LocalCluster
  # --- the browser build (scripts/web.sh; sources of its C/C++ libraries: scripts/web-sources.sh) ---
  emscripten             # C++ to WebAssembly + WebGL2 (3.1.6, with its prebuilt libc/libc++ and node tests)
  dpkg-dev               # dpkg-source: apt-get source unpacks the Debian source packages with their patches
  chromium               # the browser tests: the page in headless Chromium (WebGL 2 on SwiftShader)
  # --- tests, sanitizers, fuzzing ---
  libgtest-dev           # unit tests through ctest
  clang                  # libFuzzer builds of the readers
  libclang-rt-14-dev     # libFuzzer / sanitizer runtimes for clang 14
  python3-gdal           # conformance test: GDAL's own bilinear heights at track points
  sqlite3                # building MBTiles fixtures in tests
  ffmpeg                 # ffprobe: the video tests read the films' codec, size and frame count
  xvfb                   # the viewer's tests run in a virtual X server (xvfb-run)
  # --- conformance and benchmarks (peers we compare against) ---
  python3-gpxpy          # conformance test: gpxpy's lengths and durations on every GPX in shared/data
  gpsbabel               # benchmark peer
  gdal-bin               # benchmark peer (ogr2ogr)
  libbenchmark-dev       # micro-benchmarks in bench/
  time                   # /usr/bin/time: peak memory in the benchmark
  hyperfine              # benchmark timings without shell or fork overhead
  exiv2                  # the exiv2 tool: looking at the EXIF that the photo tests write into copies of shared photos
  osmium-tool            # benchmark peer of --places: `osmium tags-filter` on the same .osm.pbf (bench/places_read.sh)
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all ${#packages[@]} packages present"
  "$(dirname "$0")/web-sources.sh"
  exit 0
fi

SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
echo "setup: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
"$(dirname "$0")/web-sources.sh"
