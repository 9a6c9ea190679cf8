// The fuzz target of the scene loaders (docs/fuzzing.md): one input is a JSON scene, an OBJ or an
// MTL file, or a glTF asset, by its first byte. Loading it and flattening the scene may fail only
// with InputError or RuntimeError (exit 2 or 3 on the command line); a crash, a hang, another
// exception or a sanitizer report is a bug.
#pragma once

#include <cstddef>
#include <cstdint>

// libFuzzer's entry point, also driven by fuzz_driver.cpp where libFuzzer is not available.
// The first byte picks the kind: 'o' an OBJ, 'm' an MTL (loaded through a one-triangle OBJ
// that names it), 'g' a glTF asset (.gltf), 'b' a binary glTF (.glb), anything else a JSON
// scene; the rest is the file's bytes.
extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size);
