// The scene model: plain data, no GPU types. Loaders and presets produce it; bvh/ and render/
// consume it. Area lights are emissive materials on triangles; punctual lights (point, spot,
// directional) are carried in `lights`. Everything a loader can read is kept here, even what the
// integrator cannot shade yet (it then shades the closest supported material).
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/aabb.h"
#include "core/transform.h"
#include "core/vec.h"
#include "scene/node_animation.h"
#include "scene/walk/walk_map.h"

namespace penumbra {

namespace doom {
class Level;  // scene/doom/level.h
}

// A texture that is one frame of a cycle (Doom's flowing liquids, fire): the textures
// [index - frame, index - frame + frames) are the cycle's frames in order, each shown for
// secondsPerFrame; a material using any of them shows the frame the render's time picks, keeping
// its offset in the cycle (as Doom animates every frame of a sequence).
struct TextureAnimation {
    int frames = 1;  // 1: not animated
    int frame = 0;   // this texture's place in the cycle, [0, frames)
    float secondsPerFrame = 0.0f;
};

// An 8-bit RGBA image, top row first.
struct Texture {
    std::string name;  // file or lump name, for messages
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> rgba;  // width * height * 4 bytes
    bool srgb = true;                // colour data (base colour, emission); false for data maps
    TextureAnimation animation;
};

enum class Wrap { Repeat, ClampToEdge, MirroredRepeat };

// How texels are looked up between texel centres: bilinear, or the nearest texel (pixel art,
// Doom; glTF's NEAREST magFilter).
enum class Filter { Linear, Nearest };

// A material's use of a texture; texture < 0 means none. Wrap and filter are the sampler's, so
// one image can be used both ways.
struct TextureRef {
    int texture = -1;
    Wrap wrapU = Wrap::Repeat;
    Wrap wrapV = Wrap::Repeat;
    Filter filter = Filter::Linear;

    bool present() const { return texture >= 0; }
};

// One principled model (glTF metallic-roughness plus transmission); OBJ/MTL and WAD map onto it.
struct Material {
    std::string name;
    Vec3 albedo{0.8f};  // base colour / diffuse reflectance per channel, [0, 1]
    Vec3 emission{0};   // radiance leaving the front face (counter-clockwise winding), >= 0
    float metallic = 0.0f;      // [0, 1]
    float roughness = 1.0f;     // perceptual roughness, [0, 1]
    float ior = 1.5f;           // index of refraction of a dielectric, >= 1
    float transmission = 0.0f;  // [0, 1]: 1 is clear glass
    float specular = 0.0f;      // [0, 1] dielectric coat over the diffuse base (glTF: 1; 0: pure Lambert)
    // Beer-Lambert absorption inside a transmissive material: light that travels
    // absorptionDistance metres inside keeps absorptionColor of itself (glTF KHR_materials_volume's
    // attenuation colour and distance). absorptionDistance 0: clear.
    Vec3 absorptionColor{1.0f};
    float absorptionDistance = 0.0f;
    float opacity = 1.0f;       // [0, 1] coverage (MTL d, glTF alpha)
    float alphaCutoff = 0.0f;   // > 0: texels with alpha below it are holes (glTF MASK, Doom)
    bool twoSided = true;
    // A window onto the environment (a Doom sky ceiling): its front face shows the environment
    // seen through it, plus `emission` (a Doom sector's fill light). It is a light, which is how
    // light sampling finds the sky.
    bool skyPortal = false;
    // Its emission lights other surfaces but camera rays do not see it (Doom's sector light: the
    // unseen fixtures that light a room); the surface itself looks lit, not glowing.
    bool emissionHiddenFromCamera = false;
    // Whether light sampling (next event estimation) aims at it. false: only rays that hit it
    // find its light (with MIS weight 1), for large dim emitters that BSDF sampling finds well
    // and that would otherwise crowd the light list (Doom's floors and ceilings).
    bool lightSampled = true;
    TextureRef albedoTexture;             // sRGB; alpha is coverage
    TextureRef emissionTexture;           // sRGB, multiplies emission
    TextureRef normalTexture;             // tangent-space normal map, linear
    TextureRef metallicRoughnessTexture;  // linear; G = roughness, B = metallic (glTF)

    bool isEmissive() const { return maxComponent(emission) > 0.0f || skyPortal; }
};

enum class LightType { Point, Spot, Directional };

// A punctual light (glTF KHR_lights_punctual, Doom lamps). Area lights are emissive triangles.
struct Light {
    std::string name;
    LightType type = LightType::Point;
    Vec3 position{0};
    Vec3 direction{0, -1, 0};  // spot and directional: where the light travels
    Vec3 color{1};
    float intensity = 1.0f;    // candela (point, spot) or lux (directional), as glTF defines
    float range = 0.0f;        // 0: unlimited
    float radius = 0.0f;       // > 0: a sphere light of this radius (soft shadows)
    float innerConeRadians = 0.0f;
    float outerConeRadians = 0.7853982f;
    // Directional only: > 0 makes it a disk of this angular radius (the sun: 0.0047 rad), with
    // soft shadows; 0 is a delta light. At most kMaxAngularRadius.
    float angularRadius = 0.0f;
    // Moved every frame (the viewer's torch): kept out of the light BVH, bounded per frame instead.
    bool moves = false;
};

constexpr float kMaxAngularRadius = 0.7853982f;  // 45 degrees

// Linear radiance over the sphere of directions, equirectangular: column u in [0, 1) is the
// azimuth phi = 2 pi (u - 0.5) measured from -z toward +x, row v in [0, 1] the polar angle
// theta = pi v from +y, top row first. Direction (sin theta sin phi, cos theta, -sin theta cos phi).
struct EnvironmentMap {
    std::string name;  // file name or "sky", for messages
    int width = 0;
    int height = 0;
    std::vector<Vec3> radiance;  // width * height, row-major
};

// Light from infinitely far away: the map when there is one, else Scene::background, plus the
// procedural sky's sun; all scaled by intensity and turned by rotation about +y.
struct Environment {
    std::optional<EnvironmentMap> map;
    std::optional<Light> sun;  // directional, map-local direction (see distantLights)
    float intensity = 1.0f;
    float rotationDegrees = 0.0f;
    // Light sampling aims shadow rays at it. Off where its light is better found through geometry
    // (a Doom level's sky, seen through its sky ceilings, which are sampled as emitters): then
    // only rays that escape see it, and it is not sampled twice.
    bool sampled = true;
};

// An indexed triangle mesh with one material. normals and uvs are either empty or one per
// position; missing normals mean flat shading.
struct Mesh {
    std::string name;
    std::vector<Vec3> positions;
    std::vector<Vec3> normals;
    std::vector<Vec2> uvs;
    std::vector<std::uint32_t> indices;  // three per triangle
    std::uint32_t material = 0;
    float lightLevel = -1.0f;  // Doom sector light level in [0, 1]; -1 when the format has none

    std::size_t triangleCount() const { return indices.size() / 3; }
};

// An analytic sphere; it emits from its outside when its material is emissive.
struct Sphere {
    Vec3 center{0};
    float radius = 1.0f;  // metres, > 0
    std::uint32_t material = 0;
};

// Spheres that move and turn as one object in the viewer (the caffeine molecule's atoms):
// indices into Scene::spheres (scene/sphere_groups.h).
struct SphereGroup {
    std::string name;
    std::vector<std::uint32_t> spheres;
};

// An upright card that turns about the vertical through `position` to face each ray's origin (a
// billboard: Doom's sprites), alpha tested with its material's base-colour texture. That texture
// holds `rotations` views side by side (1, or 8 seen from 45-degree steps around the thing); the
// camera's direction from the thing, relative to `facing`, picks the view, as Doom does.
struct Sprite {
    Vec3 position{0};      // on the card's vertical axis; the extents below are relative to it
    Vec3 facing{1, 0, 0};  // horizontal unit direction the thing faces (view 1 is seen from there)
    float left = -0.5f, right = 0.5f;  // horizontal extent along the card, metres (viewer's right > 0)
    float bottom = 0.0f, top = 1.0f;   // vertical extent above position.y, metres
    std::uint32_t rotations = 1;       // 1 or 8
    std::uint32_t material = 0;
};

struct Camera {
    Vec3 position{0, 0, 1};
    Vec3 lookAt{0, 0, 0};
    Vec3 up{0, 1, 0};
    float fovYDegrees = 40.0f;    // vertical field of view
    float apertureRadius = 0.0f;  // thin-lens radius in metres; 0 is a pinhole
    float focusDistance = 0.0f;   // metres along the view direction to the sharp plane; 0: the look-at distance

    bool operator==(const Camera&) const = default;
};

// A camera path (scene files' "camera_path", docs/SCENES.md): keyframes the camera passes
// through; scene/animation.h puts the camera where the path says at a moment.
struct CameraKey {
    double time = 0;  // seconds, strictly increasing along the path
    Vec3 position{0};
    Vec3 lookAt{0, 0, -1};
    float fovYDegrees = 40.0f;  // loaders fill it from the scene's camera when a key has none
};

enum class PathInterpolation { CatmullRom, Linear };

struct CameraPath {
    std::vector<CameraKey> keys;  // empty: the camera stands still
    PathInterpolation interpolation = PathInterpolation::CatmullRom;
};

// A light carried with the camera (the Doom renderer's handheld torch): a point light placed at
// the camera, slightly below eye level, whenever the scene is rendered.
struct Torch {
    bool enabled = false;
    Vec3 color{1.0f, 0.85f, 0.6f};  // warm, like a flame or an old bulb
    float intensity = 80.0f;        // candela: lights a Doom room of ~10 m to a visible level
    float range = 0.0f;             // 0: unlimited
};

// Geometry placed many times is stored once (docs/SCENES.md "instances"; scene/instances.h): a
// prototype is a group of meshes in its own object space, and each instance places one prototype
// with an affine transform. The renderer gives each prototype one bottom-level BVH.
struct Prototype {
    std::string name;
    std::vector<Mesh> meshes;  // object space; materials index Scene::materials
};

struct Instance {
    std::uint32_t prototype = 0;
    Affine transform;  // object to world; invertible
};

// A level made of square tiles, walked one tile at a time (the dungeon preset; the viewer's grid
// movement, interact/grid_walk.h). Tile (x, z) covers [origin + (x, z) * tileSize, + tileSize).
struct TileGrid {
    float tileSize = 2.0f;  // metres
    Vec3 origin{0};         // the corner of tile (0, 0) with the least x and z, at floor height
    int width = 0, depth = 0;            // tiles along +x and +z
    std::vector<std::uint8_t> walkable;  // width * depth, index z * width + x: 1 where one can stand
    float eyeHeight = 1.6f;              // metres above the floor

    bool canStand(int x, int z) const {
        return x >= 0 && z >= 0 && x < width && z < depth && walkable[std::size_t(z) * std::size_t(width) + std::size_t(x)] != 0;
    }
};

struct Scene {
    std::string name;
    std::vector<Material> materials;
    std::vector<Mesh> meshes;  // world space, each drawn once
    std::vector<Prototype> prototypes;
    std::vector<Instance> instances;  // none: every mesh is in `meshes`
    // Instances whose transform follows animated nodes (glTF animations; scene/animation.h).
    std::vector<InstanceAnimation> instanceAnimations;
    std::vector<Sphere> spheres;
    std::vector<SphereGroup> sphereGroups;  // a sphere is in at most one
    std::vector<Sprite> sprites;
    std::vector<Texture> textures;
    std::vector<Light> lights;
    Camera camera;
    CameraPath cameraPath;  // moves the camera over time (scene/animation.h); empty: still
    Vec3 background{0};  // radiance of rays that leave the scene (when environment has no map)
    Environment environment;
    Torch torch;
    // The bounce from which the viewer's Russian roulette may end paths, where the scene's kind is
    // known to do better than ViewSettings::rouletteStart at equal time (Doom levels: 2).
    std::optional<std::uint32_t> viewerRouletteStart;
    // Doom levels: the lines walking collides with (map units); none where a format has no levels.
    std::optional<walk::WalkMap> walkMap;
    // Doom levels: the level as loaded, with its line specials and the instances that carry its
    // moving floors and ceilings (scene/doom/level.h); the viewer plays a copy of it.
    std::shared_ptr<const doom::Level> doomLevel;
    // Tile-map levels: the grid the viewer's grid movement steps on.
    std::optional<TileGrid> tileGrid;

    std::size_t triangleCount() const;
    Aabb bounds() const;  // meshes, instances, spheres and sprites
    // Throws Error naming the mesh, sphere, sprite or texture and the problem (index out of range, non-finite vertex,
    // bad material id, ...). Loaders call it before handing a scene on.
    void validate() const;
};

// One triangle with everything the renderer needs, in world space.
struct SceneTriangle {
    Vec3 p[3];
    Vec3 n[3];  // shading normals (the geometric normal when the mesh has none)
    Vec2 uv[3];
    std::uint32_t material = 0;
};

// The box a sprite's card stays inside whichever way it turns.
Aabb spriteBounds(const Sprite& sprite);

// Adds the torch, when enabled, as a point light at the camera (call after the camera is final).
void attachTorch(Scene& scene);

// Bytes the scene model holds in memory (vector payloads), for `penumbra info`.
std::size_t sceneBytes(const Scene& scene);

// All triangles of the scene's meshes in mesh order (instances are not among them).
std::vector<SceneTriangle> flattenTriangles(const Scene& scene);
// One mesh's triangles, appended in order, in the mesh's own space.
void appendTriangles(const Mesh& mesh, std::vector<SceneTriangle>& out);

// Checks a camera and throws a UsageError naming the problem (look-at equal to the position,
// up parallel to the view direction, field of view outside (0, 180), negative aperture or
// focus distance).
void validateCamera(const Camera& camera);

// The distance along the view direction at which the camera is sharp: focusDistance, or the
// look-at distance when that is 0.
float effectiveFocusDistance(const Camera& camera);

}  // namespace penumbra
