#include "vulkan_rt/compute_mode/embree_tree.h"

#include "util/error.h"

#include <algorithm>
#include <new>

#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

namespace tp {
namespace {

// Embree builds into nodes that we allocate through its thread-local allocator (the memory
// belongs to the RTCBVH object) and hands back the root. An inner node is one allocation: the
// builder is binary (maxBranchingFactor 2).
void* create_node(RTCThreadLocalAllocator alloc, unsigned int children, void*) {
    auto* n = new (rtcThreadLocalAlloc(alloc, sizeof(TreeInner), alignof(TreeInner))) TreeInner();
    n->children = std::min(children, 2u);
    return n;
}

void set_children(void* node, void** children, unsigned int n, void*) {
    auto* inner = static_cast<TreeInner*>(node);
    inner->children = std::min<uint32_t>(inner->children, n);
    for (unsigned int i = 0; i < inner->children; ++i)
        inner->child[i] = static_cast<TreeNode*>(children[i]);
}

void set_bounds(void* node, const RTCBounds** bounds, unsigned int n, void*) {
    auto* inner = static_cast<TreeInner*>(node);
    for (unsigned int i = 0; i < n && i < inner->children; ++i) inner->bounds[i] = *bounds[i];
}

void* create_leaf(RTCThreadLocalAllocator alloc, const RTCBuildPrimitive* prims, size_t n, void*) {
    auto* leaf = new (rtcThreadLocalAlloc(alloc, sizeof(TreeLeaf), 16)) TreeLeaf();
    leaf->count = uint32_t(n);
    leaf->items = static_cast<uint32_t*>(rtcThreadLocalAlloc(alloc, n * sizeof(uint32_t), 4));
    for (size_t i = 0; i < n; ++i) leaf->items[i] = prims[i].primID;
    return leaf;
}

} // namespace

RTCBuildPrimitive make_primitive(vec3 lo, vec3 hi, uint32_t id) {
    RTCBuildPrimitive p;
    p.lower_x = lo.x;
    p.lower_y = lo.y;
    p.lower_z = lo.z;
    p.geomID = 0;
    p.upper_x = hi.x;
    p.upper_y = hi.y;
    p.upper_z = hi.z;
    p.primID = id;
    return p;
}

RTCBounds merge_bounds(const RTCBounds& a, const RTCBounds& b) {
    return RTCBounds{std::min(a.lower_x, b.lower_x), std::min(a.lower_y, b.lower_y),
                     std::min(a.lower_z, b.lower_z), 0.0f,
                     std::max(a.upper_x, b.upper_x), std::max(a.upper_y, b.upper_y),
                     std::max(a.upper_z, b.upper_z), 0.0f};
}

RTCBounds bounds_of(const std::vector<RTCBuildPrimitive>& prims) {
    const RTCBounds empty{FLOAT_MAX,  FLOAT_MAX,  FLOAT_MAX,  0.0f,
                          -FLOAT_MAX, -FLOAT_MAX, -FLOAT_MAX, 0.0f};
    return tbb::parallel_reduce(
        tbb::blocked_range<size_t>(0, prims.size(), 4096), empty,
        [&](const tbb::blocked_range<size_t>& r, RTCBounds all) {
            for (size_t i = r.begin(); i != r.end(); ++i) {
                const RTCBuildPrimitive& p = prims[i];
                all = merge_bounds(all, RTCBounds{p.lower_x, p.lower_y, p.lower_z, 0.0f, p.upper_x,
                                                  p.upper_y, p.upper_z, 0.0f});
            }
            return all;
        },
        merge_bounds);
}

EmbreeTreeBuilder::EmbreeTreeBuilder() {
    device_ = rtcNewDevice(nullptr);
    if (!device_) runtime_error("cannot create an Embree device for the GPU BVH");
}

EmbreeTreeBuilder::~EmbreeTreeBuilder() {
    if (bvh_) rtcReleaseBVH(bvh_);
    rtcReleaseDevice(device_);
}

TreeNode* EmbreeTreeBuilder::build(std::vector<RTCBuildPrimitive>& prims, uint32_t max_leaf,
                                   uint32_t max_depth) {
    if (bvh_) rtcReleaseBVH(bvh_);
    bvh_ = rtcNewBVH(device_);
    RTCBuildArguments args = rtcDefaultBuildArguments();
    args.buildQuality = RTC_BUILD_QUALITY_MEDIUM; // binned SAH, no spatial splits
    args.maxBranchingFactor = 2;
    args.maxDepth = max_depth;
    args.minLeafSize = 1;
    args.maxLeafSize = max_leaf;
    args.traversalCost = 1.0f;
    args.intersectionCost = 1.0f;
    args.bvh = bvh_;
    args.primitives = prims.data();
    args.primitiveCount = prims.size();
    args.primitiveArrayCapacity = prims.size();
    args.createNode = create_node;
    args.setNodeChildren = set_children;
    args.setNodeBounds = set_bounds;
    args.createLeaf = create_leaf;
    auto* root = static_cast<TreeNode*>(rtcBuildBVH(&args));
    const RTCError error = rtcGetDeviceError(device_);
    if (!root || error != RTC_ERROR_NONE) {
        if (error == RTC_ERROR_OUT_OF_MEMORY)
            runtime_error("out of host memory while building the GPU BVH");
        runtime_error("Embree could not build the GPU BVH");
    }
    return root;
}

} // namespace tp
