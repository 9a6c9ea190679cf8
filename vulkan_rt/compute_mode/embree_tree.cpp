#include "vulkan_rt/compute_mode/embree_tree.h"

#include "util/error.h"

#include <algorithm>
#include <new>

namespace tp {
namespace {

// Embree builds into nodes that we allocate through its thread-local allocator (the memory
// belongs to the RTCBVH object) and hands back the root.
void* create_node(RTCThreadLocalAllocator alloc, unsigned int children, void*) {
    auto* n = new (rtcThreadLocalAlloc(alloc, sizeof(TreeInner), 16)) TreeInner();
    n->children = children;
    n->child = static_cast<const TreeNode**>(
        rtcThreadLocalAlloc(alloc, children * sizeof(TreeNode*), alignof(TreeNode*)));
    n->bounds = static_cast<RTCBounds*>(
        rtcThreadLocalAlloc(alloc, children * sizeof(RTCBounds), alignof(RTCBounds)));
    return n;
}

void set_children(void* node, void** children, unsigned int n, void*) {
    auto* inner = static_cast<TreeInner*>(node);
    inner->children = std::min<uint32_t>(inner->children, n);
    for (unsigned int i = 0; i < inner->children; ++i)
        inner->child[i] = static_cast<const TreeNode*>(children[i]);
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

RTCBounds bounds_of(const std::vector<RTCBuildPrimitive>& prims) {
    RTCBounds all{FLOAT_MAX, FLOAT_MAX, FLOAT_MAX, 0.0f, -FLOAT_MAX, -FLOAT_MAX, -FLOAT_MAX, 0.0f};
    for (const RTCBuildPrimitive& p : prims) {
        all.lower_x = std::min(all.lower_x, p.lower_x);
        all.lower_y = std::min(all.lower_y, p.lower_y);
        all.lower_z = std::min(all.lower_z, p.lower_z);
        all.upper_x = std::max(all.upper_x, p.upper_x);
        all.upper_y = std::max(all.upper_y, p.upper_y);
        all.upper_z = std::max(all.upper_z, p.upper_z);
    }
    return all;
}

EmbreeTreeBuilder::EmbreeTreeBuilder() {
    device_ = rtcNewDevice(nullptr);
    if (!device_) runtime_error("cannot create an Embree device for the GPU BVH");
}

EmbreeTreeBuilder::~EmbreeTreeBuilder() {
    if (bvh_) rtcReleaseBVH(bvh_);
    rtcReleaseDevice(device_);
}

const TreeNode* EmbreeTreeBuilder::build(std::vector<RTCBuildPrimitive>& prims, uint32_t max_leaf,
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
    auto* root = static_cast<const TreeNode*>(rtcBuildBVH(&args));
    const RTCError error = rtcGetDeviceError(device_);
    if (!root || error != RTC_ERROR_NONE) {
        if (error == RTC_ERROR_OUT_OF_MEMORY)
            runtime_error("out of host memory while building the GPU BVH");
        runtime_error("Embree could not build the GPU BVH");
    }
    return root;
}

} // namespace tp
