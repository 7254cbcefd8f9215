#include "scene/io/gltf_node.h"

#include <cmath>
#include <vector>

#include "core/error.h"

namespace penumbra::gltf {

Affine nodeTransform(const tinygltf::Node& n, const std::string& where) {
    auto finite = [&](const std::vector<double>& v) {
        for (double d : v)
            if (!std::isfinite(d)) throw Error(where + ": transform has a value that is not a finite number");
    };
    Affine local;
    if (!n.matrix.empty()) {  // column-major; glTF requires the last row to be 0 0 0 1
        if (n.matrix.size() != 16) throw Error(where + ": matrix must have 16 numbers");
        finite(n.matrix);
        for (int row = 0; row < 3; ++row)
            for (int col = 0; col < 4; ++col) local.m[row][col] = float(n.matrix[std::size_t(col * 4 + row)]);
        return local;
    }
    if (!n.translation.empty() && n.translation.size() != 3) throw Error(where + ": translation must have 3 numbers");
    if (!n.rotation.empty() && n.rotation.size() != 4) throw Error(where + ": rotation must have 4 numbers");
    if (!n.scale.empty() && n.scale.size() != 3) throw Error(where + ": scale must have 3 numbers");
    finite(n.translation);
    finite(n.rotation);
    finite(n.scale);
    double x = 0, y = 0, z = 0, w = 1;
    if (n.rotation.size() == 4) {
        x = n.rotation[0], y = n.rotation[1], z = n.rotation[2], w = n.rotation[3];
        const double len = std::sqrt(x * x + y * y + z * z + w * w);
        if (len > 0 && std::isfinite(len)) x /= len, y /= len, z /= len, w /= len;
        else x = y = z = 0, w = 1;
    }
    const double sx = n.scale.size() == 3 ? n.scale[0] : 1, sy = n.scale.size() == 3 ? n.scale[1] : 1,
                 sz = n.scale.size() == 3 ? n.scale[2] : 1;
    // R * S in columns, then T.
    const double r[3][3] = {{1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)},
                            {2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)},
                            {2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)}};
    const double s[3] = {sx, sy, sz};
    for (int row = 0; row < 3; ++row)
        for (int col = 0; col < 3; ++col) local.m[row][col] = float(r[row][col] * s[col]);
    if (n.translation.size() == 3)
        for (int k = 0; k < 3; ++k) local.m[k][3] = float(n.translation[std::size_t(k)]);
    return local;
}

}  // namespace penumbra::gltf
