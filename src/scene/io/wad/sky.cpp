#include "scene/io/wad/sky.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <vector>

#include "scene/environment.h"
#include "shared/color.h"
#include "shared/constants.h"

namespace penumbra::wad {
namespace {

constexpr double kHorizonRow = 100.0;   // R_InitSkyMap: skytexturemid = 100 (rows)
constexpr double kFocalPixels = 160.0;  // half of the 320-pixel view, which spans 90 degrees
constexpr int kSkyColumns = 1024;       // angle >> ANGLETOSKYSHIFT (22): 1024 columns per turn
constexpr double kFadeRows = 32.0;

// The texture decoded to linear light, once.
struct LinearTexture {
    int width, height;
    std::vector<Vec3> texels;

    explicit LinearTexture(const Texture& t) : width(t.width), height(t.height) {
        texels.reserve(std::size_t(width) * std::size_t(height));
        for (std::size_t i = 0; i < std::size_t(width) * std::size_t(height); ++i)
            texels.push_back({shader::srgbToLinear(t.rgba[4 * i] / 255.0f),
                              shader::srgbToLinear(t.rgba[4 * i + 1] / 255.0f),
                              shader::srgbToLinear(t.rgba[4 * i + 2] / 255.0f)});
    }
    Vec3 at(int x, int y) const {
        return texels[std::size_t(y) * std::size_t(width) + std::size_t(x)];
    }
    Vec3 meanOfRows(int firstRow, int rows) const {
        Vec3 sum{0};
        int n = 0;
        for (int y = std::max(firstRow, 0); y < std::min(firstRow + rows, height); ++y)
            for (int x = 0; x < width; ++x, ++n) sum = sum + at(x, y);
        return n > 0 ? sum / float(n) : Vec3{0};
    }
};

}  // namespace

std::string skyTextureName(const std::string& mapName) {
    if (mapName.size() == 4 && mapName[0] == 'E' && mapName[2] == 'M' && mapName[1] >= '1' &&
        mapName[1] <= '4')
        return std::string("SKY") + mapName[1];
    if (mapName.size() == 5 && mapName.compare(0, 3, "MAP") == 0 &&
        std::isdigit((unsigned char)mapName[3]) && std::isdigit((unsigned char)mapName[4])) {
        const int map = (mapName[3] - '0') * 10 + (mapName[4] - '0');
        return map < 12 ? "SKY1" : map < 21 ? "SKY2" : "SKY3";
    }
    return "SKY1";
}

EnvironmentMap skyEnvironment(const Texture& skyTexture, float brightness) {
    EnvironmentMap map;
    map.name = skyTexture.name;
    map.width = kSkyMapWidth;
    map.height = kSkyMapHeight;
    map.radiance.assign(std::size_t(map.width) * std::size_t(map.height), Vec3{0});
    if (skyTexture.width <= 0 || skyTexture.height <= 0 ||
        skyTexture.rgba.size() < std::size_t(skyTexture.width) * skyTexture.height * 4)
        return map;
    const LinearTexture sky(skyTexture);
    const Vec3 capTop = sky.meanOfRows(0, 4), capBottom = sky.meanOfRows(sky.height - 4, 4);
    // The texture column of every map column and the texture row of every map row (at texel
    // centres; environmentDirection gives the map-local direction, +y up).
    std::vector<int> columns(std::size_t(map.width));
    for (int x = 0; x < map.width; ++x) {
        const Vec3 dir = environmentDirection((x + 0.5) / map.width, 0.5);
        // Doom's angle: counter-clockwise from east (+x) toward north (Doom +y = our -z).
        double angle = std::atan2(-double(dir.z), double(dir.x));
        if (angle < 0) angle += 2 * kPi;
        columns[std::size_t(x)] =
            int(std::floor(angle / (2 * kPi) * kSkyColumns)) % kSkyColumns % sky.width;
    }
    for (int y = 0; y < map.height; ++y) {
        const double elevation = kPi / 2 - kPi * (y + 0.5) / map.height;
        const double row = std::floor(kHorizonRow - kFocalPixels * std::tan(elevation));
        for (int x = 0; x < map.width; ++x) {
            const int column = columns[std::size_t(x)];
            Vec3 c;
            if (row < 0) {
                const float t = float(std::min(-row / kFadeRows, 1.0));
                c = sky.at(column, 0) * (1 - t) + capTop * t;
            } else if (row >= sky.height) {
                const float t = float(std::min((row - sky.height + 1) / kFadeRows, 1.0));
                c = sky.at(column, sky.height - 1) * (1 - t) + capBottom * t;
            } else {
                c = sky.at(column, int(row));
            }
            map.radiance[std::size_t(y) * std::size_t(map.width) + std::size_t(x)] = c * brightness;
        }
    }
    return map;
}

}  // namespace penumbra::wad
