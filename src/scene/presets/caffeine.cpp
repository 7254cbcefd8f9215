// The caffeine molecule (C8H10N4O2, PubChem CID 2519) as spheres floating over a cup's worth of
// coffee, lit by one sphere light and seen through a thin lens focused on the molecule.
//
// Atom positions (angstrom) are the optimised 3-D structure in the molecule library of the
// Atomes program (github.com/Slookeur/Atomes, bin/library/molecules/Aromatics/caffeine.sml).
// Bond lengths in it are the usual ones (C-H 1.09, C=O 1.22, C-N 1.35-1.47 angstrom), which the
// unit tests check. Radii are 0.36 x the Bondi van der Waals radii, which keeps bonded atoms apart
// (ball-and-stick proportions without the sticks); colours are CPK.
#include <cmath>
#include <iterator>

#include "scene/presets/mesh_builder.h"
#include "scene/presets/presets.h"
#include "shared/constants.h"

namespace penumbra {
namespace {

struct Atom {
    char element;  // C, H, N or O
    float x, y, z;
};

constexpr Atom kCaffeine[] = {
    {'C', 1.785021f, -0.779129f, -0.255949f},  {'C', 0.401929f, 1.318216f, -0.016004f},
    {'C', -0.733464f, 0.413478f, 0.038347f},   {'C', -0.617909f, -0.973998f, -0.109571f},
    {'C', -2.772439f, -0.562269f, 0.209813f},  {'C', 0.735608f, -3.069196f, -0.210904f},
    {'C', -2.730788f, 1.961282f, 0.459758f},   {'C', 2.908891f, 1.458603f, -0.240195f},
    {'H', -3.848274f, -0.720508f, 0.332764f},  {'H', 1.561100f, -3.446348f, -0.829847f},
    {'H', -0.192018f, -3.562176f, -0.530166f}, {'H', 0.935512f, -3.340819f, 0.835372f},
    {'H', -2.333498f, 2.706064f, -0.245137f},  {'H', -2.525360f, 2.320312f, 1.478733f},
    {'H', -3.818507f, 1.892617f, 0.326144f},   {'H', 3.674681f, 0.991531f, -0.874770f},
    {'H', 3.303682f, 1.537341f, 0.782105f},    {'H', 2.721889f, 2.471199f, -0.622647f},
    {'O', 2.892437f, -1.297551f, -0.212698f},  {'O', 0.363733f, 2.532611f, 0.115710f},
    {'N', 1.659632f, 0.660920f, -0.271271f},   {'N', 0.612806f, -1.608906f, -0.393730f},
    {'N', -2.109760f, 0.657267f, 0.234906f},   {'N', -1.874903f, -1.560540f, -0.000764f},
};

constexpr float kMetresPerAngstrom = 0.1f;  // a molecule 0.8 m across
constexpr float kRadiusScale = 0.36f;       // of the van der Waals radius
const Vec3 kMoleculeCentre{0.0f, 0.55f, 0.0f};

float vanDerWaalsRadius(char element) {  // Bondi (1964), angstrom
    switch (element) {
        case 'H': return 1.20f;
        case 'N': return 1.55f;
        case 'O': return 1.52f;
        default: return 1.70f;  // C
    }
}

}  // namespace

Scene makeCaffeine() {
    Scene scene;
    scene.name = "caffeine";
    const std::uint32_t carbon = addMaterial(scene, "carbon", {0.12f, 0.12f, 0.12f});
    const std::uint32_t hydrogen = addMaterial(scene, "hydrogen", {0.9f, 0.9f, 0.9f});
    const std::uint32_t nitrogen = addMaterial(scene, "nitrogen", {0.12f, 0.2f, 0.85f});
    const std::uint32_t oxygen = addMaterial(scene, "oxygen", {0.85f, 0.08f, 0.06f});
    const std::uint32_t coffee = addMaterial(scene, "coffee", {0.28f, 0.15f, 0.07f});
    const std::uint32_t lamp = addMaterial(scene, "lamp", Vec3{0}, {60.0f, 55.0f, 48.0f});

    // The ring plane lies in the file's xy plane; tipping it 25 degrees back about x shows the
    // molecule a little from above, as if it rose from the cup.
    const float tilt = degreesToRadians(-25.0f);
    const float c = std::cos(tilt), s = std::sin(tilt);
    Vec3 mean{0};
    for (const Atom& a : kCaffeine) mean += Vec3{a.x, a.y, a.z};
    mean = mean / float(std::size(kCaffeine));
    SphereGroup molecule{"caffeine", {}};
    for (const Atom& a : kCaffeine) {
        molecule.spheres.push_back(static_cast<std::uint32_t>(scene.spheres.size()));
        Vec3 p = Vec3{a.x, a.y, a.z} - mean;
        p = Vec3{p.x, c * p.y - s * p.z, s * p.y + c * p.z};
        const std::uint32_t material = a.element == 'H' ? hydrogen : a.element == 'N' ? nitrogen : a.element == 'O' ? oxygen : carbon;
        scene.spheres.push_back({kMoleculeCentre + p * kMetresPerAngstrom,
                                 vanDerWaalsRadius(a.element) * kRadiusScale * kMetresPerAngstrom, material});
    }

    // The viewer moves and turns the atoms as one object (scene/sphere_groups.h).
    scene.sphereGroups.push_back(std::move(molecule));

    Mesh surface;
    surface.name = "coffee";
    surface.material = coffee;
    addQuad(surface, {-10, 0, -10}, {-10, 0, 10}, {10, 0, 10}, {10, 0, -10});  // faces up
    scene.meshes.push_back(surface);

    scene.spheres.push_back({{-1.2f, 2.4f, 1.4f}, 0.3f, lamp});
    scene.background = {0.03f, 0.025f, 0.02f};

    scene.camera.position = {0.0f, 0.95f, 2.1f};
    scene.camera.lookAt = kMoleculeCentre;
    scene.camera.up = {0, 1, 0};
    scene.camera.fovYDegrees = 30.0f;
    scene.camera.apertureRadius = 0.025f;  // the far coffee surface blurs; the molecule stays sharp
    scene.camera.focusDistance = length(kMoleculeCentre - scene.camera.position);
    return scene;
}

}  // namespace penumbra
