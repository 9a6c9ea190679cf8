#!/usr/bin/env bash
# Builds the gpu-bundle preset and packs a self-contained folder for headless GPU nodes that
# have only a driver: bin/twinpath, the shared libraries it needs beyond glibc, libstdc++,
# libm, libgcc_s and the Vulkan loader (in lib/, found through the executable's RPATH), and
# the bundled scenes. Output: build-gpu-bundle/twinpath-bundle/ and twinpath-bundle.tar.xz.
# Limits: 20 MB compressed, what travels to a GPU node beside the Vulkan loader and a scene (the
# device tool carries 64 MiB in all); 80 MB unpacked, most of it Debian's Embree with every ISA.
set -euo pipefail
cd "$(dirname "$0")/.."
cmake --preset gpu-bundle >/dev/null
cmake --build --preset gpu-bundle

build=build-gpu-bundle
dest=$build/twinpath-bundle
rm -rf "$dest" "$build/twinpath-bundle.tar.xz"
mkdir -p "$dest/bin" "$dest/lib" "$dest/scenes"
cp "$build/bin/twinpath" "$dest/bin/"
# Every bundled scene: the JSON ones and the glTF example (self-contained: data URIs).
cp scenes/*.json scenes/*.gltf "$dest/scenes/"

# Libraries the node provides itself: the C runtime, the C++ runtime and the Vulkan loader.
system='^(linux-vdso|ld-linux|libc|libm|libdl|libpthread|librt|libstdc\+\+|libgcc_s|libvulkan)\.so'
ldd "$build/bin/twinpath" | awk '/=> \// {print $1, $3}' | while read -r name path; do
  if [[ ! "$name" =~ $system ]]; then cp -L "$path" "$dest/lib/$name"; fi
done

tar -C "$build" -cJf "$build/twinpath-bundle.tar.xz" twinpath-bundle
unpacked=$(du -sb "$dest" | cut -f1)
packed=$(stat -c %s "$build/twinpath-bundle.tar.xz")
echo "bundle: $dest ($((unpacked / 1000000)) MB), $build/twinpath-bundle.tar.xz ($((packed / 1000000)) MB)"
ls "$dest/lib"
if ((unpacked > 80000000 || packed > 20000000)); then
  echo "error: the bundle exceeds 80 MB unpacked or 20 MB compressed" >&2
  exit 1
fi
