# Sourced by test.sh, web.sh and fuzz.sh: compile through ccache when it is installed (setup.sh
# installs it). CMAKE_*_COMPILER_LAUNCHER arguments in `launcher`; paths under the repository are
# hashed relative to it (and the debug builds' working folder not at all), so another clone of the
# same sources, as CI makes, is served from the cache that earlier builds filled.
launcher=()
if command -v ccache >/dev/null; then
  launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
  export CCACHE_BASEDIR="${CCACHE_BASEDIR:-$PWD}" CCACHE_NOHASHDIR="${CCACHE_NOHASHDIR:-1}"
fi
