#include "cpu_ref/embree_accel.h"

#include "util/error.h"

#include <cmath>
#include <cstring>
#include <limits>

namespace tp {

namespace {
const char* embree_error_name(RTCError e) {
    switch (e) {
    case RTC_ERROR_NONE:
        return "none";
    case RTC_ERROR_INVALID_ARGUMENT:
        return "invalid argument";
    case RTC_ERROR_INVALID_OPERATION:
        return "invalid operation";
    case RTC_ERROR_OUT_OF_MEMORY:
        return "out of memory";
    case RTC_ERROR_UNSUPPORTED_CPU:
        return "unsupported CPU";
    case RTC_ERROR_CANCELLED:
        return "cancelled";
    default:
        return "unknown error";
    }
}

float embree_tfar(float tmax) {
    return tmax >= FLOAT_MAX ? std::numeric_limits<float>::infinity() : tmax;
}
} // namespace

bool EmbreeAccel::monitor(void* self, ssize_t bytes, bool) {
    static_cast<EmbreeAccel*>(self)->bytes_ += int64_t(bytes);
    return true;
}

void EmbreeAccel::check(const char* what) const {
    const RTCError e = rtcGetDeviceError(device_);
    if (e == RTC_ERROR_OUT_OF_MEMORY) runtime_error("Embree ran out of memory while {}", what);
    if (e != RTC_ERROR_NONE)
        runtime_error("Embree failed while {}: {}", what, embree_error_name(e));
}

EmbreeAccel::EmbreeAccel(const FlatScene& scene) {
    device_ = rtcNewDevice(nullptr);
    if (!device_)
        runtime_error("cannot create an Embree device: {}",
                      embree_error_name(rtcGetDeviceError(nullptr)));
    rtcSetDeviceMemoryMonitorFunction(device_, &EmbreeAccel::monitor, this);

    for (const MeshInfo& m : scene.meshes) {
        RTCScene s = rtcNewScene(device_);
        // ROBUST: no traversal shortcuts that trade watertightness for speed.
        rtcSetSceneFlags(s, RTC_SCENE_FLAG_ROBUST);
        rtcSetSceneBuildQuality(s, RTC_BUILD_QUALITY_HIGH);
        RTCGeometry g = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
        // New (Embree-owned, padded) buffers: a shared vec3 array would be read 4 bytes past
        // its end by Embree's 16-byte vertex loads.
        auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(
            g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), m.vertex_count));
        auto* i = static_cast<uint32_t*>(rtcSetNewGeometryBuffer(
            g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(uint32_t), m.triangle_count));
        check("allocating mesh buffers");
        std::memcpy(v, &scene.positions[m.first_vertex], sizeof(vec3) * m.vertex_count);
        std::memcpy(i, &scene.triangles[m.first_triangle], sizeof(uvec3) * m.triangle_count);
        rtcCommitGeometry(g);
        rtcAttachGeometryByID(s, g, 0);
        rtcReleaseGeometry(g);
        rtcCommitScene(s);
        check("building a mesh BVH");
        meshes_.push_back(s);
    }

    top_ = rtcNewScene(device_);
    rtcSetSceneFlags(top_, RTC_SCENE_FLAG_ROBUST);
    for (uint32_t k = 0; k < scene.instances.size(); ++k) {
        const Instance& inst = scene.instances[k];
        RTCGeometry g = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_INSTANCE);
        rtcSetGeometryInstancedScene(g, meshes_[inst.mesh]);
        const float rows[12] = {inst.to_world0.x, inst.to_world0.y, inst.to_world0.z,
                                inst.to_world0.w, inst.to_world1.x, inst.to_world1.y,
                                inst.to_world1.z, inst.to_world1.w, inst.to_world2.x,
                                inst.to_world2.y, inst.to_world2.z, inst.to_world2.w};
        rtcSetGeometryTransform(g, 0, RTC_FORMAT_FLOAT3X4_ROW_MAJOR, rows);
        rtcCommitGeometry(g);
        rtcAttachGeometryByID(top_, g, k);
        rtcReleaseGeometry(g);
    }
    rtcCommitScene(top_);
    check("building the instance BVH");
}

EmbreeAccel::~EmbreeAccel() {
    if (top_) rtcReleaseScene(top_);
    for (RTCScene s : meshes_) rtcReleaseScene(s);
    if (device_) rtcReleaseDevice(device_);
}

Hit EmbreeAccel::intersect(const Ray& ray) const {
    RTCIntersectContext ctx;
    rtcInitIntersectContext(&ctx);
    RTCRayHit rh;
    rh.ray.org_x = ray.origin.x;
    rh.ray.org_y = ray.origin.y;
    rh.ray.org_z = ray.origin.z;
    rh.ray.dir_x = ray.dir.x;
    rh.ray.dir_y = ray.dir.y;
    rh.ray.dir_z = ray.dir.z;
    rh.ray.tnear = 0.0f;
    rh.ray.tfar = embree_tfar(ray.tmax);
    rh.ray.mask = 0xFFFFFFFFu;
    rh.ray.time = 0.0f;
    rh.ray.flags = 0;
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(top_, &ctx, &rh);
    Hit h;
    if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return h;
    h.found = true;
    h.t = rh.ray.tfar;
    h.instance = rh.hit.instID[0];
    h.primitive = rh.hit.primID;
    h.bary = vec2(rh.hit.u, rh.hit.v);
    return h;
}

bool EmbreeAccel::occluded(const Ray& ray) const {
    RTCIntersectContext ctx;
    rtcInitIntersectContext(&ctx);
    RTCRay r;
    r.org_x = ray.origin.x;
    r.org_y = ray.origin.y;
    r.org_z = ray.origin.z;
    r.dir_x = ray.dir.x;
    r.dir_y = ray.dir.y;
    r.dir_z = ray.dir.z;
    r.tnear = 0.0f;
    r.tfar = embree_tfar(ray.tmax);
    r.mask = 0xFFFFFFFFu;
    r.time = 0.0f;
    r.flags = 0;
    rtcOccluded1(top_, &ctx, &r);
    return r.tfar < 0.0f; // Embree sets tfar to -inf on a hit
}

} // namespace tp
