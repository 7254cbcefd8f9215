#include "render/walks.h"

#include <algorithm>

#include "bvh/stackless.h"
#include "core/error.h"
#include "render/object_boxes.h"
#include "shared/types.h"
#include "shared/accel_layouts.h"

namespace penumbra {

namespace {

constexpr WalkInfo kWalks[] = {
    {Accel::Bvh, "bvh", PN_ACCEL_BVH, "the default: the binary BVH, a stack, near child first"},
    {Accel::Wide, "wide", PN_ACCEL_WIDE, "the compressed 8-wide BVH; scenes with instances keep bvh"},
    {Accel::Stackless, "stackless", PN_ACCEL_STACKLESS, "the binary BVH through escape indices, no stack"},
    {Accel::Objects, "objects", PN_ACCEL_OBJECTS, "a box per object, every primitive in each box hit: a comparison"},
    {Accel::Brute, "brute", PN_ACCEL_BRUTE, "every primitive per ray: the oracle"},
};

}  // namespace

std::span<const WalkInfo> walks() { return kWalks; }

const WalkInfo& walkInfo(Accel accel) {
    for (const WalkInfo& w : kWalks)
        if (w.accel == accel) return w;
    throw Error("internal: a walk missing from render/walks.cpp");
}

std::string walkNameList() {
    std::string out;
    const std::size_t n = std::size(kWalks);
    for (std::size_t i = 0; i < n; ++i) {
        if (i > 0) out += i + 1 == n ? " or " : ", ";
        out += kWalks[i].name;
    }
    return out;
}

std::string accelHelp() {
    std::string out = "the ray walk:";
    for (const WalkInfo& w : kWalks) {
        out += ' ';
        out += w.name;
        out += " (";
        out += w.summary;
        out += ')';
        if (&w != &kWalks[std::size(kWalks) - 1]) out += ';';
    }
    return out;
}

Accel parseAccel(const std::string& name) {
    for (const WalkInfo& w : kWalks)
        if (name == w.name) return w.accel;
    throw UsageError("unknown --accel '" + name + "'; use " + walkNameList());
}

const char* accelName(Accel accel) { return walkInfo(accel).name; }

void buildWalkRecords(SceneArrays& arrays, Accel accel) {
    arrays.stacklessNodes.clear();
    arrays.objectBoxes.clear();
    arrays.objectPrims.clear();
    if (accel == Accel::Stackless && !arrays.nodes.empty()) {
        // Every tree in the node array: the flat BVH, or each bottom level and the top level.
        std::vector<std::uint32_t> roots;
        for (const shader::Instance& inst : arrays.instances) roots.push_back(inst.rootNode & ~PN_INSTANCE_IDENTITY);
        std::sort(roots.begin(), roots.end());
        roots.erase(std::unique(roots.begin(), roots.end()), roots.end());
        if (arrays.instances.empty()) roots = {0u};
        else roots.push_back(arrays.topRoot);
        if (arrays.restRoot != PN_NO_HIT) roots.push_back(arrays.restRoot);
        arrays.stacklessNodes = bvh::threadNodes(arrays.nodes, roots);
    }
    if (accel == Accel::Objects) buildObjectBoxes(arrays);
    const bool wideFallsBack = accel == Accel::Wide && arrays.wideNodes.empty();
    arrays.walk = wideFallsBack ? PN_ACCEL_BVH : walkInfo(accel).shaderId;
}

void refreshTopLevelRecords(SceneArrays& arrays) {
    if (arrays.instances.empty()) return;
    // Only the top level's escapes change: the bottom levels' nodes are untouched.
    if (!arrays.stacklessNodes.empty()) bvh::threadTree(arrays.nodes, arrays.topRoot, arrays.stacklessNodes);
    // A moved instance's box is its top-level leaf's; rebuilt whole (a comparison walk: simple wins).
    if (!arrays.objectBoxes.empty()) buildObjectBoxes(arrays);
}

}  // namespace penumbra
