#include "scene/io/wad/sky.h"

#include <algorithm>
#include <cctype>
#include <cmath>

#include "scene/environment.h"
#include "shared/color.h"

namespace penumbra::wad {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kHorizonRow = 100.0;   // R_InitSkyMap: skytexturemid = 100 (rows)
constexpr double kFocalPixels = 160.0;  // half of the 320-pixel view, which spans 90 degrees
constexpr int kSkyColumns = 1024;       // angle >> ANGLETOSKYSHIFT (22): 1024 columns per turn
constexpr double kFadeRows = 32.0;

Vec3 texel(const Texture& t, int x, int y) {
    const std::uint8_t* p = &t.rgba[(std::size_t(y) * std::size_t(t.width) + std::size_t(x)) * 4];
    return {shader::srgbToLinear(p[0] / 255.0f), shader::srgbToLinear(p[1] / 255.0f),
            shader::srgbToLinear(p[2] / 255.0f)};
}

Vec3 meanOfRows(const Texture& t, int firstRow, int rows) {
    Vec3 sum{0};
    int n = 0;
    for (int y = std::max(firstRow, 0); y < std::min(firstRow + rows, t.height); ++y)
        for (int x = 0; x < t.width; ++x, ++n) sum = sum + texel(t, x, y);
    return n > 0 ? sum / float(n) : Vec3{0};
}

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

EnvironmentMap skyEnvironment(const Texture& sky, float brightness) {
    EnvironmentMap map;
    map.name = sky.name;
    map.width = kSkyMapWidth;
    map.height = kSkyMapHeight;
    map.radiance.assign(std::size_t(map.width) * std::size_t(map.height), Vec3{0});
    if (sky.width <= 0 || sky.height <= 0 ||
        sky.rgba.size() < std::size_t(sky.width) * sky.height * 4)
        return map;
    const Vec3 capTop = meanOfRows(sky, 0, 4), capBottom = meanOfRows(sky, sky.height - 4, 4);
    for (int y = 0; y < map.height; ++y) {
        // Texel centres; environmentDirection gives the map-local direction (+y up).
        const Vec3 d = environmentDirection(0.5, (y + 0.5) / map.height);
        const double elevation = std::asin(std::clamp(double(d.y), -1.0, 1.0));
        const double row = std::floor(kHorizonRow - kFocalPixels * std::tan(elevation));
        for (int x = 0; x < map.width; ++x) {
            const Vec3 dir = environmentDirection((x + 0.5) / map.width, (y + 0.5) / map.height);
            // Doom's angle: counter-clockwise from east (+x) toward north (Doom +y = our -z).
            double angle = std::atan2(-double(dir.z), double(dir.x));
            if (angle < 0) angle += 2 * kPi;
            const int skyColumn = int(std::floor(angle / (2 * kPi) * kSkyColumns)) % kSkyColumns;
            const int column = skyColumn % sky.width;
            Vec3 c;
            if (row < 0) {
                const float t = float(std::min(-row / kFadeRows, 1.0));
                c = texel(sky, column, 0) * (1 - t) + capTop * t;
            } else if (row >= sky.height) {
                const float t = float(std::min((row - sky.height + 1) / kFadeRows, 1.0));
                c = texel(sky, column, sky.height - 1) * (1 - t) + capBottom * t;
            } else {
                c = texel(sky, column, int(row));
            }
            map.radiance[std::size_t(y) * std::size_t(map.width) + std::size_t(x)] = c * brightness;
        }
    }
    return map;
}

}  // namespace penumbra::wad
