#include "scene/io/gltf_accessor.h"

#include "core/error.h"

namespace penumbra::gltf {
namespace {

int componentSize(int type) {
    switch (type) {
        case TINYGLTF_COMPONENT_TYPE_BYTE:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return 1;
        case TINYGLTF_COMPONENT_TYPE_SHORT:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return 2;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
        case TINYGLTF_COMPONENT_TYPE_FLOAT: return 4;
    }
    return 0;
}

int componentCount(int type) {
    switch (type) {
        case TINYGLTF_TYPE_SCALAR: return 1;
        case TINYGLTF_TYPE_VEC2: return 2;
        case TINYGLTF_TYPE_VEC3: return 3;
        case TINYGLTF_TYPE_VEC4: return 4;
    }
    return 0;
}

}  // namespace

AccessorView readAccessor(const tinygltf::Model& model_, int index, const std::string& where, int wantComponents) {
    const std::string here = where + ", accessor " + std::to_string(index);
    if (index < 0 || std::size_t(index) >= model_.accessors.size())
        throw Error(here + " does not exist (" + std::to_string(model_.accessors.size()) + " accessors)");
    const tinygltf::Accessor& acc = model_.accessors[std::size_t(index)];
    if (acc.sparse.isSparse) throw Error(here + ": sparse accessors are not supported");
    AccessorView view;
    view.components = componentCount(acc.type);
    if (view.components != wantComponents)
        throw Error(here + ": expected " + std::to_string(wantComponents) + " components per element");
    const int size = componentSize(acc.componentType);
    if (size == 0) throw Error(here + ": invalid componentType " + std::to_string(acc.componentType));
    view.componentType = acc.componentType;
    view.normalized = acc.normalized && acc.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT &&
                      acc.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
    view.count = acc.count;
    if (acc.count == 0) return view;
    if (acc.bufferView < 0 || std::size_t(acc.bufferView) >= model_.bufferViews.size())
        throw Error(here + ": bufferView " + std::to_string(acc.bufferView) + " does not exist");
    const tinygltf::BufferView& bv = model_.bufferViews[std::size_t(acc.bufferView)];
    const std::string bvWhere = here + ", bufferView " + std::to_string(acc.bufferView);
    if (bv.buffer < 0 || std::size_t(bv.buffer) >= model_.buffers.size())
        throw Error(bvWhere + ": buffer " + std::to_string(bv.buffer) + " does not exist");
    const std::vector<unsigned char>& buf = model_.buffers[std::size_t(bv.buffer)].data;
    if (bv.byteLength > buf.size() || bv.byteOffset > buf.size() - bv.byteLength)
        throw Error(bvWhere + ": bytes " + std::to_string(bv.byteOffset) + "+" + std::to_string(bv.byteLength) +
                    " lie outside buffer " + std::to_string(bv.buffer) + " (" + std::to_string(buf.size()) +
                    " bytes)");
    const std::size_t elem = std::size_t(size) * std::size_t(view.components);
    view.stride = bv.byteStride ? bv.byteStride : elem;
    if (view.stride < elem || view.stride > 252)
        throw Error(bvWhere + ": byteStride " + std::to_string(bv.byteStride) + " is invalid for " +
                    std::to_string(elem) + "-byte elements");
    if (acc.byteOffset > bv.byteLength || bv.byteLength - acc.byteOffset < elem ||
        (acc.count - 1) > (bv.byteLength - acc.byteOffset - elem) / view.stride)
        throw Error(here + ": " + std::to_string(acc.count) + " elements from byte " +
                    std::to_string(acc.byteOffset) + " do not fit in the " + std::to_string(bv.byteLength) +
                    "-byte bufferView");
    view.data = buf.data() + bv.byteOffset + acc.byteOffset;
    return view;
}

}  // namespace penumbra::gltf
