// Writing a Mesh as a Wavefront OBJ (with vertex normals) or a glTF file, for tests that load
// the same geometry through the importers.
#pragma once

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "scene/scene.h"

namespace penumbra::test {

// v, vn and f v//vn lines, nine significant digits (floats round-trip exactly).
inline void writeObj(const std::filesystem::path& path, const Mesh& m) {
    std::ofstream f(path);
    f.precision(9);
    for (Vec3 v : m.positions) f << "v " << v.x << ' ' << v.y << ' ' << v.z << '\n';
    for (Vec3 n : m.normals) f << "vn " << n.x << ' ' << n.y << ' ' << n.z << '\n';
    for (std::size_t i = 0; i < m.indices.size(); i += 3) {
        f << 'f';
        for (int k = 0; k < 3; ++k)
            f << ' ' << m.indices[i + k] + 1 << "//" << m.indices[i + k] + 1;
        f << '\n';
    }
}

// NAME.gltf with its buffer in NAME.bin: positions, normals (float VEC3) and uint32 indices, in
// one node (`node`: its JSON object; the mesh is added).
inline void writeGltf(const std::filesystem::path& dir, const std::string& name, const Mesh& m,
                      nlohmann::json node = nlohmann::json::object()) {
    using Json = nlohmann::json;
    std::ofstream bin(dir / (name + ".bin"), std::ios::binary);
    const auto write = [&](const auto& v) {
        bin.write(reinterpret_cast<const char*>(v.data()),
                  std::streamsize(v.size() * sizeof(v[0])));
    };
    write(m.positions);
    write(m.normals);
    write(m.indices);
    Vec3 lo = m.positions[0], hi = m.positions[0];
    for (Vec3 v : m.positions) lo = min(lo, v), hi = max(hi, v);
    const std::size_t vertexBytes = m.positions.size() * 12, indexBytes = m.indices.size() * 4;
    node["mesh"] = 0;
    const auto view = [](std::size_t offset, std::size_t length) {
        return Json{{"buffer", 0}, {"byteOffset", offset}, {"byteLength", length}};
    };
    const Json doc = {
        {"asset", {{"version", "2.0"}}},
        {"scene", 0},
        {"scenes", {{{"nodes", {0}}}}},
        {"nodes", {node}},
        {"meshes",
         {{{"primitives", {{{"attributes", {{"POSITION", 0}, {"NORMAL", 1}}}, {"indices", 2}}}}}}},
        {"buffers", {{{"uri", name + ".bin"}, {"byteLength", 2 * vertexBytes + indexBytes}}}},
        {"bufferViews",
         {view(0, vertexBytes), view(vertexBytes, vertexBytes), view(2 * vertexBytes, indexBytes)}},
        {"accessors",
         {{{"bufferView", 0},
           {"componentType", 5126},
           {"count", m.positions.size()},
           {"type", "VEC3"},
           {"min", {lo.x, lo.y, lo.z}},
           {"max", {hi.x, hi.y, hi.z}}},
          {{"bufferView", 1},
           {"componentType", 5126},
           {"count", m.normals.size()},
           {"type", "VEC3"}},
          {{"bufferView", 2},
           {"componentType", 5125},
           {"count", m.indices.size()},
           {"type", "SCALAR"}}}}};
    std::ofstream(dir / (name + ".gltf")) << doc.dump(1);
}

}  // namespace penumbra::test
