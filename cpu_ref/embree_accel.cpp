#include "cpu_ref/embree_accel.h"

#include "scene/world_vertex.h"
#include "shared/surface.h"
#include "util/error.h"

#include <algorithm>
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

RTCScene EmbreeAccel::new_scene() const {
    RTCScene s = rtcNewScene(device_);
    // Not RTC_SCENE_FLAG_ROBUST: the grown triangles make Embree's fast test conservative and the
    // filter exact (exact_triangles.h), where the robust mode alone leaks at vertices and takes
    // 14-17 % more time (docs/stress.md).
    rtcSetSceneBuildQuality(s, RTC_BUILD_QUALITY_HIGH);
    return s;
}

void EmbreeAccel::attach_mesh(RTCScene s, uint32_t id, const FlatScene& scene, const MeshInfo& m,
                              const Instance* to_world, double camera_extent) {
    ExactMesh& exact = exact_.emplace_back();
    const vec3* p = &scene.positions[m.first_vertex];
    exact.vertices.resize(m.vertex_count);
    for (uint32_t k = 0; k < m.vertex_count; ++k)
        // The vertices compute mode's one-level BVH holds too (scene/world_vertex.h).
        exact.vertices[k] = to_world ? world_vertex(*to_world, p[k]) : p[k];
    exact.triangles.assign(scene.triangles.begin() + m.first_triangle,
                           scene.triangles.begin() + m.first_triangle + m.triangle_count);

    RTCGeometry g = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
    // New (Embree-owned, padded) buffers: a shared vec3 array would be read 4 bytes past its end
    // by Embree's 16-byte vertex loads. Three unshared vertices per triangle: each grows its own.
    auto* v =
        static_cast<vec3*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                   sizeof(vec3), 3 * size_t(m.triangle_count)));
    auto* i = static_cast<uvec3*>(rtcSetNewGeometryBuffer(
        g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, sizeof(uvec3), m.triangle_count));
    check("allocating mesh buffers");
    exact.margin = grow_triangles(exact, exact_delta(mesh_extent(exact, camera_extent)), v);
    for (uint32_t k = 0; k < m.triangle_count; ++k) i[k] = uvec3(3 * k, 3 * k + 1, 3 * k + 2);
    rtcSetGeometryUserData(g, &exact);
    rtcSetGeometryIntersectFilterFunction(g, exact_intersect_filter);
    rtcSetGeometryOccludedFilterFunction(g, exact_occluded_filter);
    rtcCommitGeometry(g);
    rtcAttachGeometryByID(s, g, id);
    rtcReleaseGeometry(g);
}

EmbreeAccel::EmbreeAccel(const FlatScene& scene) {
    device_ = rtcNewDevice(nullptr);
    if (!device_)
        runtime_error("cannot create an Embree device: {}",
                      embree_error_name(rtcGetDeviceError(nullptr)));
    rtcSetDeviceMemoryMonitorFunction(device_, &EmbreeAccel::monitor, this);

    // Each mesh grows by the delta of its own neighbourhood (exact_triangles.h, mesh_extent): the
    // camera is the world's origin, so a world-space mesh needs only its vertices; an instanced
    // mesh adds the eye's image in object space, to_object(0), for each of its instances.
    // A mesh that one instance uses goes into the top-level scene as world-space triangles: a
    // one-level BVH saves the instance transform and a second traversal per ray (BENCHMARKS.md,
    // local-peer). A mesh that several instances share is built once and instanced.
    const std::vector<uint32_t> uses = instances_per_mesh(scene);
    meshes_.assign(scene.meshes.size(), nullptr);
    for (uint32_t k = 0; k < scene.meshes.size(); ++k) {
        if (uses[k] < 2) continue;
        double camera_extent = 0.0;
        for (const Instance& inst : scene.instances)
            if (inst.mesh == k) {
                const vec3 eye = glm::abs(instance_point_to_object(inst, vec3(0.0f)));
                camera_extent =
                    std::max(camera_extent, double(glm::max(eye.x, glm::max(eye.y, eye.z))));
            }
        RTCScene s = new_scene();
        attach_mesh(s, 0, scene, scene.meshes[k], nullptr, camera_extent);
        rtcCommitScene(s);
        check("building a mesh BVH");
        meshes_[k] = s;
    }

    top_ = new_scene();
    for (uint32_t k = 0; k < scene.instances.size(); ++k) {
        const Instance& inst = scene.instances[k];
        if (!meshes_[inst.mesh]) {
            attach_mesh(top_, k, scene, scene.meshes[inst.mesh], &inst, 0.0);
            continue;
        }
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
    check("building the top-level BVH");
}

EmbreeAccel::~EmbreeAccel() {
    if (top_) rtcReleaseScene(top_);
    for (RTCScene s : meshes_)
        if (s) rtcReleaseScene(s);
    if (device_) rtcReleaseDevice(device_);
}

// The hit Embree ended a ray's query with (geometry, instance and triangle), exact (exact_hit).
Hit EmbreeAccel::exact_result(const ExactRecord& record, uint32_t geom, uint32_t inst,
                              uint32_t prim) {
    Hit h;
    if (geom == RTC_INVALID_GEOMETRY_ID) return h;
    h.found = true;
    const vec3 tuv = exact_hit(record, prim);
    h.t = tuv.x;
    // A flattened mesh's triangles carry their instance index as geometry ID (constructor).
    h.instance = inst != RTC_INVALID_GEOMETRY_ID ? inst : geom;
    h.primitive = prim;
    h.bary = vec2(tuv.y, tuv.z);
    return h;
}

Hit EmbreeAccel::intersect(const Ray& ray, const CoverageTest* coverage) const {
    ExactRecord record;
    ExactQuery query;
    rtcInitIntersectContext(&query.context);
    query.records = &record;
    query.coverage = coverage;
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
    rtcIntersect1(top_, &query.context, &rh);
    return exact_result(record, rh.hit.geomID, rh.hit.instID[0], rh.hit.primID);
}

void EmbreeAccel::intersect_packet(const Ray* rays, uint32_t count, Hit* hits) const {
    ExactRecord records[kPacket];
    ExactQuery query;
    rtcInitIntersectContext(&query.context);
    query.context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
    query.records = records;
    alignas(32) int valid[kPacket];
    alignas(32) RTCRayHit8 rh;
    for (uint32_t i = 0; i < kPacket; ++i) {
        valid[i] = i < count ? -1 : 0;
        const Ray& ray = rays[i < count ? i : 0];
        rh.ray.org_x[i] = ray.origin.x;
        rh.ray.org_y[i] = ray.origin.y;
        rh.ray.org_z[i] = ray.origin.z;
        rh.ray.dir_x[i] = ray.dir.x;
        rh.ray.dir_y[i] = ray.dir.y;
        rh.ray.dir_z[i] = ray.dir.z;
        rh.ray.tnear[i] = 0.0f;
        rh.ray.tfar[i] = embree_tfar(ray.tmax);
        rh.ray.mask[i] = 0xFFFFFFFFu;
        rh.ray.time[i] = 0.0f;
        rh.ray.flags[i] = 0;
        rh.hit.geomID[i] = RTC_INVALID_GEOMETRY_ID;
        rh.hit.instID[0][i] = RTC_INVALID_GEOMETRY_ID;
    }
    rtcIntersect8(valid, top_, &query.context, &rh);
    for (uint32_t i = 0; i < count; ++i)
        hits[i] = exact_result(records[i], rh.hit.geomID[i], rh.hit.instID[0][i], rh.hit.primID[i]);
}

bool EmbreeAccel::occluded(const Ray& ray, const CoverageTest* coverage) const {
    ExactQuery query; // occlusion records nothing
    rtcInitIntersectContext(&query.context);
    query.coverage = coverage;
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
    rtcOccluded1(top_, &query.context, &r);
    return r.tfar < 0.0f; // Embree sets tfar to -inf on a hit
}

} // namespace tp
