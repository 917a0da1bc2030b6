#!/usr/bin/env bash
# The C and C++ libraries the WebAssembly build compiles from source: Emscripten cannot link
# Debian's x86 binaries and its "ports" download from the internet, so the sources come from
# Debian's own source packages (the same versions as the -dev packages the native build links).
# Unpacked, with Debian's patches, into third_party/debian-src/<package>/ (ignored by git).
# Idempotent: a package already unpacked is kept. Called by scripts/setup.sh.
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(
  geographiclib   # geodesics and local frames (geo/), as in the native build
  zlib            # .gz tracks, and KMZ through libzip
  libzip          # KMZ archives (track/io/zip_archive)
  libpng1.6       # PNG tiles and pictures (terrain/codecs/image_codec)
  libjpeg-turbo   # JPEG imagery tiles (terrain/codecs/image_codec, through its TurboJPEG API)
  libwebp         # WebP tiles (terrain/codecs/image_codec)
  freetype        # the legend's text (scene/)
  imgui           # Dear ImGui (the page's panels), the same 1.86 as libimgui-dev
)

dest=third_party/debian-src
mkdir -p "$dest"
missing=()
for p in "${packages[@]}"; do
  [ -f "$dest/$p/.unpacked" ] || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "web-sources: all ${#packages[@]} source packages present"
  exit 0
fi

SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
# apt-get source needs a deb-src entry; Debian's default list on a fresh machine has none.
list=/etc/apt/sources.list.d/trailray-deb-src.sources
if ! grep -rqs "deb-src" /etc/apt/sources.list /etc/apt/sources.list.d/; then
  printf '%s\n' "Types: deb-src" "URIs: http://deb.debian.org/debian" "Suites: bookworm" \
    "Components: main" "Signed-By: /usr/share/keyrings/debian-archive-keyring.gpg" | $SUDO tee "$list" >/dev/null
  $SUDO apt-get update -qq
fi

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
for p in "${missing[@]}"; do
  echo "web-sources: fetching Debian source package $p"
  (cd "$work" && apt-get source -qq "$p" 2>&1 | grep -v "^W: Download is performed unsandboxed" || true)
  unpacked=$(find "$work" -mindepth 1 -maxdepth 1 -type d -name "${p}-*" | head -1)
  [ -n "$unpacked" ] || { echo "web-sources: apt-get source $p unpacked nothing" >&2; exit 1; }
  rm -rf "${dest:?}/$p"
  mv "$unpacked" "$dest/$p"
  touch "$dest/$p/.unpacked"
  rm -rf "${work:?}"/*
done
