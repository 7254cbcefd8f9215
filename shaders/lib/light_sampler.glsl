// The unified light sampler: one pick among every light in the scene, by its estimated
// contribution at the shading point, then one sample of that light, so every shading vertex
// sends one shadow ray whatever the mix of lights.
//
// The lights are LightRef entries (render/light_list.h). The first frame.topLightCount are
// weighed one by one at every point: the environment (pi times its mean luminance), directional
// lights (illuminance times the cosine bound at the surface) and lights that move every frame
// (their LightNode). Everything bounded in space sits in a light BVH whose root competes with
// them; the pick descends it choosing children in proportion to their importance (Conty Estevez
// & Kulla 2018; pbrt-v4's BVHLightSampler): power over squared distance, times bounds on the
// emitter's and the surface's cosines. lightPickPmf retraces the same choices along the light's
// bit trail, so MIS uses exactly the probability sampling had. The bounds are most of a pick's
// cost (on the H200, about 0.6 of DOOM1 E1M1's 1.5 ms shading pass at 1080p), so only the first
// PN_LIGHT_TREE_IMPORTANCE_LEVELS levels evaluate them; below, clusters are small and children
// are chosen by power. The tree's nodes (LightTreeNode) carry what the bound needs precomputed,
// and the bound spends as few square roots and divisions as it can. Where the tree is deeper than
// those levels and the scene has a light grid (render/light_grid.h), the tree is not walked at
// all: the cell that holds the point and the bin of its normal hold an alias table over the
// clusters on that level, weighed by the same bound widened to the whole cell and bin, and the
// tree's weight against the top-level lights; each cluster holds an alias table over its lights
// by power. MIS reads the drawn probabilities back from the same tables.
#ifndef PN_LIGHT_SAMPLER_GLSL
#define PN_LIGHT_SAMPLER_GLSL

#include "lib/sampling.glsl"
#include "lib/rng.glsl"
#include "lib/lights.glsl"
#include "lib/sphere_lights.glsl"
#include "lib/sun.glsl"
#include "lib/environment.glsl"
#include "lib/mis.glsl"
#include "lib/offset.glsl"
#include "lib/bvh.glsl"
#include "shared/light_importance.h"

float lightNodeImportance(LightNode node, vec3 p, vec3 n) {
    vec3 halfDiagonal = 0.5 * (node.boundsMax - node.boundsMin);
    return clusterImportance(LightCluster(node.boundsMin + halfDiagonal, length(halfDiagonal), node.axis, node.phi,
                                          node.cosThetaO, node.sinThetaO, node.cosThetaE, node.twoSided != 0u), p, n);
}

float treeNodeImportance(LightTreeNode node, vec3 p, vec3 n) {
    return clusterImportance(LightCluster(node.center, node.radius, node.axis, node.phi, node.cosThetaO, node.sinThetaO,
                                          node.cosThetaE, (node.childOrLight & PN_LIGHT_NODE_TWO_SIDED) != 0u), p, n);
}

// A directional light's illuminance times the best cosine at the surface over its disk.
float directionalImportance(PunctualLight l, vec3 n) {
    float cosI = abs(dot(n, l.direction));
    float cosR = 1.0 - l.coneOneMinusCos;
    return luminance(l.intensity) * cosSubClamped(sinFromCos(cosI), cosI, sinFromCos(cosR), cosR);
}

float topLightImportance(uint k, vec3 p, vec3 n) {
    LightRef r = lights[k];
    if (r.type == PN_LIGHTREF_ENVIRONMENT) return PN_PI * frame.envLuminance * frame.envIntensity;
    if (r.index >= frame.punctualCount) return 0.0;  // the viewer's torch, switched off
    PunctualLight l = punctualLights[r.index];
    if (l.type == PN_LIGHT_DIRECTIONAL) return directionalImportance(l, n);
    return lightNodeImportance(lightNodes[k], p, n);
}

// The tree's importance plus every top-level light's: the normaliser of every pick at p.
float totalLightImportance(float tree, vec3 p, vec3 n) {
    float total = tree;
    uint count = PN_OPTION(PN_OPTION_ONE_TOP_LIGHT) ? 1u : frame.topLightCount;
    for (uint k = 0u; k < count; ++k) total += topLightImportance(k, p, n);
    return total;
}

// One level of the walk: the children of an interior node whose childOrLight is `node` (at
// `depth`, the root's 0), their own childOrLight words, and the probability of the first; -1 when
// neither can light p. The first levels choose by the children's importance at p; deeper, where
// clusters are small, by their power alone, which spares two importance bounds per level (most of
// a pick's cost). pickLight and lightPickPmf choose alike at every node, so the pmf stays exact.
// The walk carries one word per node rather than whole nodes, and each child is read, weighed and
// dropped in turn, which keeps the shading kernel's registers down.
float firstChildProbability(uint node, vec3 p, vec3 n, uint depth, out uint first, out uint second) {
    uint record = node & PN_LIGHT_NODE_INDEX;
    first = lightTree[record].childOrLight;
    second = lightTree[record + 1u].childOrLight;
    if (depth >= PN_LIGHT_TREE_IMPORTANCE_LEVELS) {
        float phiFirst = lightTree[record].phi;
        return phiFirst / (phiFirst + lightTree[record + 1u].phi);
    }
    float a = treeNodeImportance(lightTree[record], p, n), b = treeNodeImportance(lightTree[record + 1u], p, n);
    return a + b > 0.0 ? a / (a + b) : -1.0;
}

struct LightPick {
    uint ref;   // LightRef index; PN_NO_LIGHT: no light can reach p
    float pmf;  // probability of this pick at p
};

// The light grid (render/light_grid.h): the words after the tree's records in its buffer, and
// its header, element frame.lightGridOffset / PN_LIGHT_GRID_PREFIXES of the same buffer seen as
// headers (shared/lights.h).
layout(std430, set = 0, binding = PN_BINDING_LIGHT_TREE) readonly buffer LightGridBuffer { uint lightGrid[]; };
layout(std430, set = 0, binding = PN_BINDING_LIGHT_TREE) readonly buffer LightGridHeaderBuffer {
    LightGridHeader lightGridHeaders[];
};
#define PN_LIGHT_GRID_HEADER lightGridHeaders[frame.lightGridOffset / PN_LIGHT_GRID_PREFIXES]

// The grid's table for the cell that holds p and the bin of normal n (cell * PN_LIGHT_GRID_BINS +
// bin); PN_NO_HIT where the walk weighs the tree's first levels itself: no grid, no surface, or p
// off the grid.
uint lightGridTable(vec3 p, vec3 n) {
    uint base = frame.lightGridOffset;
    if (!PN_HAS(PN_FEATURE_LIGHT_GRID) || base == 0u) return PN_NO_HIT;
    return lightGridTableIndex((p - PN_LIGHT_GRID_HEADER.origin) * PN_LIGHT_GRID_HEADER.inverseCellSize,
                               PN_LIGHT_GRID_HEADER.cellsX, PN_LIGHT_GRID_HEADER.cellsY, PN_LIGHT_GRID_HEADER.cellsZ, n);
}

// The first word of a grid table's alias entries.
uint lightGridTableWord(uint table) {
    uint base = frame.lightGridOffset;
    return base + PN_LIGHT_GRID_HEADER.firstTable + table * 2u * PN_LIGHT_GRID_HEADER.clusterCount;
}

// The light tree's weight at p against the top-level lights, and its root's childOrLight; 0 when
// the scene has no tree. Where the grid has a table for p, the table's bound of the root over the
// whole cell and bin stands in for the root's bound at p (one bound fewer per pick and per pmf;
// pickLight and lightPickPmf both use it, so the pmf stays exact).
float lightTreeWeight(vec3 p, vec3 n, uint table, out uint root) {
    root = 0u;
    if (frame.lightNodeCount == 0u) return 0.0;
    if (table != PN_NO_HIT) {
        uint base = frame.lightGridOffset;
        root = lightTree[0].childOrLight;
        return uintBitsToFloat(lightGrid[base + PN_LIGHT_GRID_HEADER.firstTree + table]);
    }
    LightTreeNode node = lightTree[0];
    root = node.childOrLight;
    return treeNodeImportance(node, p, n);
}

// A grid table entry's probability: its mass over the table's.
float lightGridProbability(uint mass, uint clusters) { return float(mass) / float(clusters << PN_LIGHT_GRID_MASS_BITS); }

// One draw from the alias table of `count` entries at word `entries` of the grid (Vose's alias
// method, on integers: the probability drawn is exactly the mass the table stores): an entry's index.
uint aliasDraw(uint entries, uint count, inout uint rng) {
    uint slot, low;
    umulExtended(rngNextUint(rng), count, slot, low);  // floor(bits * count / 2^32)
    uint entry = lightGrid[entries + 2u * slot];
    uint coin = rngNextUint(rng) >> (32u - PN_LIGHT_GRID_MASS_BITS);
    return coin < (entry & PN_LIGHT_GRID_THRESHOLD_MASK) ? slot : entry >> PN_LIGHT_GRID_ALIAS_SHIFT;
}

// A cluster drawn from a grid table; pmf is multiplied by its probability.
uint pickGridCluster(uint table, inout float pmf, inout uint rng) {
    uint clusters = PN_LIGHT_GRID_HEADER.clusterCount;
    uint cluster = aliasDraw(table, clusters, rng);
    pmf *= lightGridProbability(lightGrid[table + 2u * cluster + 1u], clusters);
    return cluster;
}

// A grid cluster's words: its node word and level (where a walk goes on below it), its first
// light entry and its lights (0: walk below it).
uvec4 lightGridCluster(uint cluster) {
    uint base = frame.lightGridOffset;
    uint at = base + PN_LIGHT_GRID_PREFIXES + (1u << PN_LIGHT_GRID_HEADER.levels) + PN_LIGHT_GRID_CLUSTER_WORDS * cluster;
    return uvec4(lightGrid[at], lightGrid[at + 1u], lightGrid[at + 2u], lightGrid[at + 3u]);
}

// A light's probability within its grid cluster (lights > 0): its mass over the cluster's.
float lightInClusterProbability(uint ref, uint lights) {
    uint base = frame.lightGridOffset;
    return lightGridProbability(lightGrid[base + PN_LIGHT_GRID_HEADER.firstMass + ref], lights);
}

// A light of a grid cluster drawn by power from the cluster's alias table: the choice the walk
// below the cluster would make, in one draw. pmf: the cluster's probability.
LightPick pickInCluster(uvec4 cluster, float pmf, inout uint rng) {
    uint entries = frame.lightGridOffset + cluster.z;
    uint ref = lightGrid[entries + 2u * aliasDraw(entries, cluster.w, rng) + 1u];
    return LightPick(ref, pmf * lightInClusterProbability(ref, cluster.w));
}

// The first choice of a pick in a kernel specialised for one top-level light
// (PN_OPTION_ONE_TOP_LIGHT, a WAD level's torch), with u in [0, 1): the light (returns false,
// `pick` is final) or the tree (returns true, `pick` holds the tree's probability). The light's
// bound is weighed once, where pickLight's loop weighs each top-level light twice (once for the
// normaliser, once to choose); the numbers are the same, so lightPickPmf agrees.
bool pickBesideOneTopLight(vec3 p, vec3 n, float u, float tree, out LightPick pick) {
    pick = LightPick(PN_NO_LIGHT, 0.0);
    float w = topLightImportance(0u, p, n);
    float total = tree + w;
    if (!(total > 0.0)) return false;
    if (w > 0.0) {
        pick = LightPick(0u, w / total);
        if (u * total < w || !(tree > 0.0)) return false;
    }
    pick = LightPick(PN_NO_LIGHT, tree / total);
    return true;
}

// Picks among the top-level lights with u in [0, 1) (a stratified number: a scene with a few
// lights gives each its share of a pixel's samples), then down the light tree with fresh numbers
// from rng: u rescaled level after level would keep too few of its 24 bits to choose fairly deep
// in a tree of many emitters. Uniform picks take 32 random bits, exact for any count.
LightPick pickLight(vec3 p, vec3 n, float u, inout uint rng) {
    if (frame.lightPickUniform != 0u) {
        if (frame.lightRefCount == 0u) return LightPick(PN_NO_LIGHT, 0.0);
        uint k, low;
        umulExtended(rngNextUint(rng), frame.lightRefCount, k, low);  // floor(bits * count / 2^32)
        return LightPick(k, 1.0 / float(frame.lightRefCount));
    }
    uint node;
    uint table = lightGridTable(p, n);
    float tree = lightTreeWeight(p, n, table, node);
    LightPick pick = LightPick(PN_NO_LIGHT, 0.0);
    if (PN_OPTION(PN_OPTION_ONE_TOP_LIGHT)) {
        if (!pickBesideOneTopLight(p, n, u, tree, pick)) return pick;
    } else {
        float total = totalLightImportance(tree, p, n);
        if (!(total > 0.0)) return LightPick(PN_NO_LIGHT, 0.0);
        float x = u * total;
        for (uint k = 0u; k < frame.topLightCount; ++k) {
            float w = topLightImportance(k, p, n);
            if (!(w > 0.0)) continue;
            pick = LightPick(k, w / total);
            if (x < w) return pick;
            x -= w;
        }
        if (!(tree > 0.0)) return pick;  // rounding carried x past the last top-level light
        pick = LightPick(PN_NO_LIGHT, tree / total);
    }
    uint depth = 0u;
    if (table != PN_NO_HIT) {
        uvec4 cluster = lightGridCluster(pickGridCluster(lightGridTableWord(table), pick.pmf, rng));
        if (!(pick.pmf > 0.0)) return LightPick(PN_NO_LIGHT, 0.0);
        if (cluster.w != 0u) return pickInCluster(cluster, pick.pmf, rng);
        node = cluster.x;
        depth = cluster.y;
    }
    for (; depth < PN_LIGHT_TREE_MAX_DEPTH; ++depth) {
        if ((node & PN_LIGHT_NODE_LEAF) != 0u) return LightPick(node & PN_LIGHT_NODE_INDEX, pick.pmf);
        uint first, second;
        float p1 = firstChildProbability(node, p, n, depth, first, second);
        if (p1 < 0.0) break;
        if (rngNext(rng) < p1) {
            node = first;
            pick.pmf *= p1;
        } else {
            node = second;
            pick.pmf *= 1.0 - p1;
        }
    }
    return LightPick(PN_NO_LIGHT, 0.0);
}

// The probability that pickLight(p, n) returns `ref`.
float lightPickPmf(uint ref, vec3 p, vec3 n) {
    if (frame.lightPickUniform != 0u) return 1.0 / float(frame.lightRefCount);
    uint node;
    uint table = lightGridTable(p, n);
    float tree = lightTreeWeight(p, n, table, node);
    float total = totalLightImportance(tree, p, n);
    if (!(total > 0.0)) return 0.0;
    if (ref < frame.topLightCount) return topLightImportance(ref, p, n) / total;
    float pmf = tree / total;
    LightRef r = lights[ref];
    uint depth = 0u;
    if (table != PN_NO_HIT) {
        uint base = frame.lightGridOffset;
        uint prefixMask = (1u << PN_LIGHT_GRID_HEADER.levels) - 1u;
        uint index = lightGrid[base + PN_LIGHT_GRID_PREFIXES + (r.trailLo & prefixMask)];
        pmf *= lightGridProbability(lightGrid[lightGridTableWord(table) + 2u * index + 1u], PN_LIGHT_GRID_HEADER.clusterCount);
        uvec4 cluster = lightGridCluster(index);
        if (cluster.w != 0u) return pmf * lightInClusterProbability(ref, cluster.w);
        node = cluster.x;
        depth = cluster.y;
    }
    for (; depth < PN_LIGHT_TREE_MAX_DEPTH; ++depth) {
        if ((node & PN_LIGHT_NODE_LEAF) != 0u) return (node & PN_LIGHT_NODE_INDEX) == ref ? pmf : 0.0;
        uint first, second;
        float p1 = firstChildProbability(node, p, n, depth, first, second);
        if (p1 < 0.0) return 0.0;
        bool takeSecond = (depth < 32u ? (r.trailLo >> depth) : (r.trailHi >> (depth - 32u))) % 2u != 0u;
        if (takeSecond) {
            node = second;
            pmf *= 1.0 - p1;
        } else {
            node = first;
            pmf *= p1;
        }
    }
    return 0.0;
}

// What an emitter's front face sends toward a viewer looking along `direction`: its emission, or
// for a sky portal the environment seen along `direction` plus its emission. Hidden emission
// (Doom's sector light) is not seen by camera rays.
vec3 emittedRadiance(Material m, vec2 uv, vec3 direction, bool cameraRay) {
    bool hidden = cameraRay && (m.flags & PN_MATERIAL_HIDDEN_EMISSION) != 0u;
    if (PN_HAS(PN_FEATURE_SKY_PORTALS) && (m.flags & PN_MATERIAL_SKY_PORTAL) != 0u)
        return environmentRadiance(direction) + (hidden ? vec3(0.0) : m.emission);
    return hidden ? vec3(0.0) : materialEmission(m, uv);
}

// One sample of a chosen light, seen from p (shading normal n).
struct LightSample {
    vec3 wi;        // unit, toward the light
    float dist;     // to the sampled point; PN_INFINITY for distant lights
    vec3 target;    // where a shadow ray aims (finite lights): the sampled point, moved off the
                    // emitter's surface toward p so that the ray never meets the emitter itself
    vec3 radiance;  // arriving along -wi (or, for a delta light, irradiance-like intensity)
    float pdf;      // solid angle, the pick included; for a delta light the pick's probability
    bool isDelta;   // BSDF sampling can never find it: no MIS
};

LightSample sampleChosenLight(LightPick pick, vec3 p, vec3 n, inout uint rng) {
    LightSample ls = LightSample(vec3(0.0, 0.0, 1.0), PN_INFINITY, p, vec3(0.0), 0.0, false);
    LightRef r = lights[pick.ref];
    vec2 u = rngNext2(rng);
    if (r.type == PN_LIGHTREF_TRIANGLE) {
        TrianglePoint tp = sampleTrianglePoint(r.index, u);
        vec3 toLight = tp.position - p;
        float dist2 = dot(toLight, toLight);
        if (!(dist2 > 0.0)) return ls;
        ls.dist = sqrt(dist2);
        ls.wi = toLight / ls.dist;
        float cosLight = -dot(tp.normal, ls.wi);
        if (cosLight <= 0.0) return ls;
        ls.radiance = tp.radiance;
        if (PN_HAS(PN_FEATURE_SKY_PORTALS)) {
            Material m = materials[triAttribs[r.index].materialId];
            if ((m.flags & PN_MATERIAL_SKY_PORTAL) != 0u) ls.radiance = emittedRadiance(m, vec2(0.0), ls.wi, false);
        }
        ls.pdf = pick.pmf / tp.area * dist2 / cosLight;
        ls.target = offsetRayOrigin(tp.position, tp.normal);
    } else if (r.type == PN_LIGHTREF_SPHERE) {
        SphereLightSample ss = sampleSphereLight(sphereLights[r.index], p, u);
        ls.wi = ss.wi;
        ls.dist = length(ss.position - p);
        ls.target = ss.lightOnly ? ss.position : offsetRayOrigin(ss.position, ss.normal);
        ls.radiance = ss.radiance;
        ls.pdf = pick.pmf * ss.pdf;
        // A spot light with a radius has no geometry: BSDF sampling never reaches it.
        ls.isDelta = ss.lightOnly;
    } else if (r.type == PN_LIGHTREF_PUNCTUAL) {
        if (r.index >= frame.punctualCount) return ls;  // the viewer's torch, switched off
        PunctualLight l = punctualLights[r.index];
        if (isSunDisk(l)) {
            ls.wi = sampleSunDisk(l, u);
            ls.radiance = sunRadiance(l);
            ls.pdf = pick.pmf * sunConePdf(l);
        } else {
            ls.radiance = punctualIncident(l, p, ls.wi, ls.dist);
            ls.target = l.position;
            ls.pdf = pick.pmf;
            ls.isDelta = true;
        }
    } else {
        EnvSample es = sampleEnvironment(n, rng);
        ls.wi = es.direction;
        ls.radiance = es.radiance;
        ls.pdf = pick.pmf * es.pdf;
    }
    return ls;
}

// The shadow ray from `origin` (already off the shading point's surface) to a light sample.
// Both ends are off their surfaces, so the ray meets neither the shading surface nor the emitter
// itself, however far from the world's origin they are. tMax 0: the ends coincide, nothing blocks.
struct ShadowRay {
    vec3 origin;
    vec3 direction;
    float tMax;
};

ShadowRay shadowRayTo(vec3 origin, LightSample ls) {
    if (ls.dist == PN_INFINITY) return ShadowRay(origin, ls.wi, PN_INFINITY);
    vec3 span = ls.target - origin;
    float length2 = dot(span, span);
    if (!(length2 > 0.0)) return ShadowRay(origin, ls.wi, 0.0);
    float len = sqrt(length2);
    return ShadowRay(origin, span / len, len * (1.0 - 1e-4));
}

bool shadowRayBlocked(vec3 origin, LightSample ls) {
    ShadowRay r = shadowRayTo(origin, ls);
    return r.tMax > 0.0 && traceOccluded(r.origin, r.direction, r.tMax);
}

// The solid-angle pdf with which light sampling at the previous vertex (position p, shading
// normal n) would have produced a BSDF-sampled ray's hit on an emitter: the pick's probability
// times a triangle's area pdf converted to solid angle, or a sphere's cone pdf.
float emitterHitPdf(Hit hit, Surface s, vec3 p, vec3 n, vec3 origin, vec3 direction) {
    float pick = lightPickPmf(s.lightIndex, p, n);
    if (!(pick > 0.0)) return 0.0;
    float cosLight = dot(s.geometricNormal, -direction);
    TriVerts tv = triVerts[hit.triangle];
    if ((tv.flags & PN_TRI_SPHERE) != 0u) return pick * sphereDirectionPdf(tv.v0, tv.e1.x, origin, hit.t, cosLight);
    return pick / s.area * hit.t * hit.t / max(cosLight, 1e-12);
}

// Light carried by a ray that left the scene along `direction` after a BSDF sample at the
// previous vertex (position p, shading normal n; bsdfPdf 0 for a camera ray or a delta lobe, where
// no light sampling competes): the environment and any sun disk it points into, MIS-weighted.
vec3 escapedRadiance(vec3 p, vec3 n, vec3 direction, float bsdfPdf) {
    const bool unsampled = !(bsdfPdf > 0.0);
    vec3 L = vec3(0.0);
    bool environmentSampled = false;
    for (uint k = 0u; k < frame.topLightCount; ++k) {
        LightRef r = lights[k];
        if (r.type == PN_LIGHTREF_ENVIRONMENT) {
            environmentSampled = true;
            float pick = unsampled ? 0.0 : lightPickPmf(k, p, n);
            float lightPdf = pick > 0.0 ? pick * environmentPdf(direction, n) : 0.0;
            L += environmentRadiance(direction) * misWeightHit(bsdfPdf, lightPdf, unsampled);
            continue;
        }
        if (r.type != PN_LIGHTREF_PUNCTUAL || r.index >= frame.punctualCount) continue;
        PunctualLight l = punctualLights[r.index];
        if (!isSunDisk(l) || !insideSunDisk(l, direction)) continue;
        float pick = unsampled ? 0.0 : lightPickPmf(k, p, n);
        L += sunRadiance(l) * misWeightHit(bsdfPdf, pick * sunConePdf(l), unsampled);
    }
    // An environment left out of light sampling (none, or a Doom sky) is found by escaping rays only.
    if (!environmentSampled && frame.envIntensity > 0.0) L += environmentRadiance(direction);
    return L;
}

#endif
