#include "scene/gltf_accessor.h"

#include "util/error.h"

#include <algorithm>
#include <cstring>

namespace tp {
namespace {

template <typename T>
T load(const char* p) {
    T v;
    std::memcpy(&v, p, sizeof v); // glTF data is little-endian, as every host twinpath runs on
    return v;
}

// One component at p as a double, normalized per section 3.11 when asked.
double component(const char* p, uint32_t type, bool normalized) {
    switch (type) {
    case GLTF_BYTE: {
        const double v = load<int8_t>(p);
        return normalized ? std::max(v / 127.0, -1.0) : v;
    }
    case GLTF_UNSIGNED_BYTE: {
        const double v = load<uint8_t>(p);
        return normalized ? v / 255.0 : v;
    }
    case GLTF_SHORT: {
        const double v = load<int16_t>(p);
        return normalized ? std::max(v / 32767.0, -1.0) : v;
    }
    case GLTF_UNSIGNED_SHORT: {
        const double v = load<uint16_t>(p);
        return normalized ? v / 65535.0 : v;
    }
    case GLTF_UNSIGNED_INT:
        return load<uint32_t>(p);
    default:
        return load<float>(p);
    }
}

// `count` elements of `n` components from `bytes` at `offset`, `stride` bytes apart.
void read_elements(std::string_view bytes, uint64_t offset, uint64_t stride, uint32_t count,
                   uint32_t n, uint32_t type, bool normalized, double* out) {
    const uint32_t size = gltf_component_size(type);
    for (uint32_t e = 0; e < count; ++e) {
        const char* p = bytes.data() + offset + e * stride;
        for (uint32_t c = 0; c < n; ++c)
            out[size_t(e) * n + c] = component(p + c * size, type, normalized);
    }
}

} // namespace

std::vector<double> read_gltf_accessor(const GltfDocument& d, const GltfResources& res,
                                       uint32_t accessor, const std::string& field) {
    const GltfAccessor& a = d.accessors[accessor];
    if (a.type.rfind("MAT", 0) == 0)
        input_error("{}: {}: accessors[{}] is a {}, not a vector or scalar", d.path, field,
                    accessor, a.type);
    const uint32_t n = a.components, size = gltf_component_size(a.component_type);
    std::vector<double> out(size_t(a.count) * n, 0.0);
    if (a.buffer_view != GLTF_NONE) {
        const uint32_t stride = d.buffer_views[size_t(a.buffer_view)].byte_stride;
        read_elements(res.view_bytes(uint32_t(a.buffer_view)), a.byte_offset,
                      stride != 0 ? stride : n * size, a.count, n, a.component_type, a.normalized,
                      out.data());
    }
    if (a.sparse_count > 0) {
        std::vector<double> index(a.sparse_count), values(size_t(a.sparse_count) * n);
        read_elements(res.view_bytes(uint32_t(a.sparse_indices_view)), a.sparse_indices_offset,
                      gltf_component_size(a.sparse_indices_type), a.sparse_count, 1,
                      a.sparse_indices_type, false, index.data());
        read_elements(res.view_bytes(uint32_t(a.sparse_values_view)), a.sparse_values_offset,
                      n * size, a.sparse_count, n, a.component_type, a.normalized, values.data());
        for (uint32_t i = 0; i < a.sparse_count; ++i) {
            if (index[i] >= a.count || (i > 0 && index[i] <= index[i - 1]))
                input_error("{}: accessors[{}].sparse.indices: element {} is {}, but the indices "
                            "must increase and stay below count {}",
                            d.path, accessor, i, index[i], a.count);
            std::copy_n(values.begin() + long(i) * n, n, out.begin() + long(index[i]) * n);
        }
    }
    return out;
}

std::vector<uint32_t> read_gltf_indices(const GltfDocument& d, const GltfResources& res,
                                        uint32_t accessor, const std::string& field) {
    const GltfAccessor& a = d.accessors[accessor];
    if (a.type != "SCALAR" || a.normalized ||
        (a.component_type != GLTF_UNSIGNED_BYTE && a.component_type != GLTF_UNSIGNED_SHORT &&
         a.component_type != GLTF_UNSIGNED_INT))
        input_error("{}: {}: accessors[{}] must be a SCALAR of unsigned byte, short or int "
                    "(5121, 5123, 5125), not normalized; it is a {} of {}",
                    d.path, field, accessor, a.type, a.component_type);
    const std::vector<double> v = read_gltf_accessor(d, res, accessor, field);
    return std::vector<uint32_t>(v.begin(), v.end());
}

} // namespace tp
