# Sourced by test.sh, web.sh, fuzz.sh and quick-test.sh: compile through ccache when it is installed (setup.sh
# installs it). CMAKE_*_COMPILER_LAUNCHER arguments in `launcher`; paths under the repository are
# hashed relative to it (and the debug builds' working folder not at all), so another clone of the
# same sources, as CI makes, is served from the cache that earlier builds filled.
launcher=()
if command -v ccache >/dev/null; then
  launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
  export CCACHE_BASEDIR="${CCACHE_BASEDIR:-$PWD}" CCACHE_NOHASHDIR="${CCACHE_NOHASHDIR:-1}"
  # The targets' precompiled headers (cmake/CompileTime.cmake): without these, ccache compiles
  # every file that uses one without caching it. GCC's precompiled headers are the same in every
  # clone, so the Release tree still hits across clones; clang's (the sanitizer and WebAssembly
  # trees) record the build folder's path, so those hit only in the clone that filled the cache.
  # The cold build is what CI's time limit is about; test.sh's stage times show which it was.
  export CCACHE_SLOPPINESS="${CCACHE_SLOPPINESS:-pch_defines,time_macros,include_file_mtime,include_file_ctime}"
fi
