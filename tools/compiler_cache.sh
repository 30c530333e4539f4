# Sourced by tools/build.sh and tools/hardened_build.sh: the CMake arguments that put ccache
# (Debian's `ccache`, installed by tools/install_deps.sh) in front of the compilers, in
# `compiler_cache_args`. What it saves: a rebuild of the same checkout after `rm -rf build`, a
# branch switched back, and in another checkout the units that use no precompiled header. Units
# that use one (most: the touchdown_pch_* targets) miss in a checkout in another folder, because
# GCC's .gch embeds the paths it was built from (seen on a clean clone in /tmp: most of its
# compiles missed a warm cache). ccache runs in its depend mode: it keys a compile on the
# compiler's own dependency list (-MD, which CMake's Ninja rules pass) instead of running the
# preprocessor first, which a cold cache paid on every unit. Cold builds of `touchdown_quickstart`
# on the 2-core machine (2026-11-29, an empty cache each, other builds running beside them):
# without ccache 433 CPU-s, ccache's default mode 501 (+16 %), depend mode 461; a rebuild after
# `ninja -t clean` hits all 52 cacheable units in depend mode (5 s). The cached object is the
# compiler's own output for the same input and flags, so results do not change.
# TOUCHDOWN_NO_CCACHE=1 turns it off.
compiler_cache_args=()
if [ -z "${TOUCHDOWN_NO_CCACHE:-}" ] && command -v ccache >/dev/null 2>&1; then
  export CCACHE_BASEDIR="$root"
  export CCACHE_NOHASHDIR=1
  # Precompiled headers (the project's touchdown_pch_* targets) are cacheable only with these.
  export CCACHE_SLOPPINESS=pch_defines,time_macros,include_file_mtime,include_file_ctime
  export CCACHE_MAXSIZE=${CCACHE_MAXSIZE:-10G}
  export CCACHE_DEPEND=1
  compiler_cache_args=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
fi
