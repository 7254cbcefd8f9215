// The wavefront trace pass's working state (render/passes/wavefront_pass.h): every path of a tile
// has a slot; its state, its closest hit and its queued shadow ray live in buffers between the
// kernels (wave_start, wave_extend, wave_shade, wave_shadow, wave_tail, wave_finish), so that
// each kernel holds only what its own step needs. Fields are stored field-major (field * stride
// + slot), so a subgroup's loads of one field are contiguous. Everything is stored as uint bits:
// moves of integers are exact, whatever the values. Include after lib/path.glsl.
#ifndef PN_WAVE_STATE_GLSL
#define PN_WAVE_STATE_GLSL

#extension GL_KHR_shader_subgroup_ballot : require

layout(std430, set = 0, binding = PN_BINDING_WAVE_PATHS) buffer WavePaths { uvec4 wavePaths[]; };
layout(std430, set = 0, binding = PN_BINDING_WAVE_HITS) buffer WaveHits { uvec4 waveHits[]; };
layout(std430, set = 0, binding = PN_BINDING_WAVE_SHADOWS) buffer WaveShadows { uvec4 waveShadows[]; };
layout(std430, set = 0, binding = PN_BINDING_WAVE_QUEUES) buffer WaveQueues { uint waveQueues[]; };
layout(std430, set = 0, binding = PN_BINDING_WAVE_CONTROL) buffer WaveControlBuffer { WaveControl control; };

uvec4 packVec(vec3 v, uint w) { return uvec4(floatBitsToUint(v), w); }
uvec4 packVec(vec3 v, float w) { return uvec4(floatBitsToUint(v), floatBitsToUint(w)); }
vec3 unpackVec(uvec4 u) { return uintBitsToFloat(u.xyz); }
uvec4 pathField(uint field, uint slot) { return wavePaths[field * push.waveStride + slot]; }
void setPathField(uint field, uint slot, uvec4 value) { wavePaths[field * push.waveStride + slot] = value; }

// The slot's pixel (x, y) and which of the pass's samples it is (z).
uvec3 slotPixel(uint slot) {
    uint tilePixels = push.tileWidth * push.tileHeight;
    uint local = slot % tilePixels;
    return uvec3(push.tileX + local % push.tileWidth, push.tileY + local / push.tileWidth, slot / tilePixels);
}
// The sample index of the path in a slot whose slotPixel is p (what startPath seeds it with).
uint pathSampleIndex(uvec3 p) { return push.passIndex * frame.samplesPerPass + p.z; }
uint slotOf(uvec2 pixel, uint sampleInPass) {
    return sampleInPass * push.tileWidth * push.tileHeight + (pixel.y - push.tileY) * push.tileWidth + pixel.x - push.tileX;
}

// Under PN_TRACE_SHARED_CAMERA a pixel's paths start on one camera ray: bounce 0 traces it for the
// pixel's first sample only, and the others read that slot's hit (hitSlot).
bool camerasShared() { return (push.mode & PN_TRACE_SHARED_CAMERA) != 0u && push.waveBounce == 0u; }
uint hitSlot(uint slot) { return camerasShared() ? slot % (push.tileWidth * push.tileHeight) : slot; }

const uint PN_WAVE_AFTER_DELTA = 0x80000000u;

// Field 3 holds the radiance gathered so far: only a vertex that adds light reads and writes it
// (addToPathResult). Fields 5 and 6 (the previous vertex) are read only where MIS or an escape
// needs them (loadPathForShading), never after a camera ray or a delta lobe, so such paths do not
// store them. The sample index is the slot's (pathSampleIndex), never stored.
void storePath(uint slot, Path p) {
    setPathField(0u, slot, packVec(p.origin, p.bsdfPdfPrev));
    setPathField(1u, slot, packVec(p.direction, p.depth | (p.afterDelta ? PN_WAVE_AFTER_DELTA : 0u)));
    setPathField(2u, slot, packVec(p.throughput, p.rng));
    if (PN_HAS(PN_FEATURE_ABSORPTION)) setPathField(4u, slot, packVec(p.medium, 0u));
    if (!p.afterDelta) {
        setPathField(5u, slot, packVec(p.previousNormal, 0u));
        setPathField(6u, slot, packVec(p.previousPosition, 0u));
    }
}

vec3 pathResult(uint slot) { return unpackVec(pathField(3u, slot)); }
void setPathResult(uint slot, vec3 result) { setPathField(3u, slot, packVec(result, 0u)); }
void startPathResult(uint slot) { setPathResult(slot, vec3(0.0)); }

// The path's stored fields but its result and the previous vertex (zero). `pixel` is slotPixel(slot).
Path loadPathCore(uint slot, uvec3 pixel) {
    Path p;
    uvec4 f0 = pathField(0u, slot), f1 = pathField(1u, slot), f2 = pathField(2u, slot);
    p.origin = unpackVec(f0);
    p.bsdfPdfPrev = uintBitsToFloat(f0.w);
    p.direction = unpackVec(f1);
    p.depth = f1.w & ~PN_WAVE_AFTER_DELTA;
    p.afterDelta = (f1.w & PN_WAVE_AFTER_DELTA) != 0u;
    p.throughput = unpackVec(f2);
    p.rng = f2.w;
    p.result = vec3(0.0);
    p.sampleIndex = pathSampleIndex(pixel);
    p.medium = PN_HAS(PN_FEATURE_ABSORPTION) ? unpackVec(pathField(4u, slot)) : vec3(0.0);
    p.previousNormal = vec3(0.0);
    p.previousPosition = vec3(0.0);
    return p;
}

void loadPreviousVertex(inout Path p, uint slot) {
    p.previousNormal = unpackVec(pathField(5u, slot));
    p.previousPosition = unpackVec(pathField(6u, slot));
}

// The path at its hit, with the previous vertex only where the vertex will need it: an escape,
// or a hit on a light-sampled emitter after a non-delta bounce (MIS weights its emission).
// Its result starts at zero: the shade step adds what the vertex gathers to the stored one.
Path loadPathForShading(uint slot, uvec3 pixel, Hit hit) {
    Path p = loadPathCore(slot, pixel);
    if (!p.afterDelta && (hit.triangle == PN_NO_HIT || triAttribs[hit.triangle].lightIndex != PN_NO_LIGHT))
        loadPreviousVertex(p, slot);
    return p;
}

// The whole path before its next ray, its result included (wave_tail.comp adds to it in order).
Path loadPathToFinish(uint slot, uvec3 pixel) {
    Path p = loadPathCore(slot, pixel);
    if (!p.afterDelta) loadPreviousVertex(p, slot);
    p.result = pathResult(slot);
    return p;
}

void addToPathResult(uint slot, vec3 light) { setPathResult(slot, pathResult(slot) + light); }

void storeHit(uint slot, Hit h) {
    waveHits[slot] = uvec4(floatBitsToUint(h.t), h.triangle, floatBitsToUint(h.u), floatBitsToUint(h.v));
    if (PN_HAS(PN_FEATURE_INSTANCES)) waveHits[push.waveStride + slot].x = h.instance;
}

Hit loadHit(uint slot) {
    uvec4 u = waveHits[slot];
    uint instance = PN_HAS(PN_FEATURE_INSTANCES) ? waveHits[push.waveStride + slot].x : PN_NO_HIT;
    return Hit(uintBitsToFloat(u.x), u.y, uintBitsToFloat(u.z), uintBitsToFloat(u.w), instance);
}

// A shadow ray's record also says whether its path goes on after the vertex that queued it: in a
// round the tail takes, the tail traces those rays itself (tracePendingShadow) and the shadow pass
// the others, so the two run side by side.
void storeShadow(uint index, uint slot, PendingShadow s, bool pathGoesOn) {
    waveShadows[index] = packVec(s.ray.origin, s.ray.tMax);
    waveShadows[push.waveStride + index] = packVec(s.ray.direction, slot);
    waveShadows[2u * push.waveStride + index] = packVec(s.light, pathGoesOn ? 1u : 0u);
}

bool shadowPathGoesOn(uint index) { return waveShadows[2u * push.waveStride + index].w != 0u; }

// The queued shadow ray `index`: its ray, the light it carries, and (out) its path's slot.
PendingShadow loadShadow(uint index, out uint slot) {
    uvec4 a = waveShadows[index], b = waveShadows[push.waveStride + index], c = waveShadows[2u * push.waveStride + index];
    slot = b.w;
    return PendingShadow(ShadowRay(unpackVec(a), unpackVec(b), uintBitsToFloat(a.w)), unpackVec(c), true);
}

// A path that goes on keeps the index + 1 of the shadow ray its last vertex queued (0: none) in
// the w of its result field, which nothing else reads; a shade step sets it for every path it
// keeps, so it is never stale.
void setPendingShadow(uint slot, uint indexPlusOne) { wavePaths[3u * push.waveStride + slot].w = indexPlusOne; }

// The tail's first step for a path it takes: the shadow ray the path's last vertex queued, traced
// and added here rather than by that round's shadow pass, in the same order (the vertex's own
// light was added first). Returns whether there was one.
bool tracePendingShadow(uint slot, inout vec3 result) {
    uint pending = pathField(3u, slot).w;
    if (pending == 0u) return false;
    uint owner;
    PendingShadow s = loadShadow(pending - 1u, owner);
    if (!traceOccluded(s.ray.origin, s.ray.direction, s.ray.tMax)) result = result + s.light;
    return true;
}

// Appends for the invocations that want to: one atomic on the queue's counter per workgroup (its
// subgroups first reserve their runs in a workgroup total), offsets by ballot. Returns the
// invocation's index in the queue (meaningless where !want). Call from every invocation, in
// uniform control flow (it has barriers).
shared uint appendGroupCount;
shared uint appendGroupBase;
uint appendIndex(bool want, uint counter) {
    uvec4 ballot = subgroupBallot(want);
    uint total = subgroupBallotBitCount(ballot);
    if (gl_LocalInvocationIndex == 0u) appendGroupCount = 0u;
    barrier();
    uint offset = 0u;
    if (subgroupElect() && total != 0u) offset = atomicAdd(appendGroupCount, total);
    barrier();
    if (gl_LocalInvocationIndex == 0u && appendGroupCount != 0u)
        appendGroupBase = counter == 2u ? atomicAdd(control.shadowCount, appendGroupCount)
                                        : atomicAdd(control.rayCount[counter], appendGroupCount);
    barrier();
    return appendGroupBase + subgroupBroadcastFirst(offset) + subgroupBallotExclusiveBitCount(ballot);
}

// PN_WAVE_CAMERA_IN_PLACE: bounce 0 makes its camera paths in place, every slot live in order.
bool cameraInPlace() { return pnCamera == PN_CAMERA_IN_PLACE && PN_WAVE_MAKES_CAMERA_PATHS(push.mode, push.waveBounce); }

// The queue a bounce reads (its live paths) and the one it fills for the next bounce.
uint queueIn(uint i) { return waveQueues[(push.waveBounce & 1u) * push.waveStride + i]; }
void queueNext(uint i, uint slot) { waveQueues[((push.waveBounce + 1u) & 1u) * push.waveStride + i] = slot; }
uint liveRays() { return cameraInPlace() ? push.itemCount : control.rayCount[push.waveBounce & 1u]; }
// The slot of this bounce's i-th live path.
uint liveSlot(uint i) { return cameraInPlace() ? i : queueIn(i); }

// The camera path the start step stores for the slot whose pixel is p.
Path cameraPath(uvec3 p) {
    return startPath(p.xy, p.y * frame.width + p.x, pathSampleIndex(p), (push.mode & PN_TRACE_SHARED_CAMERA) != 0u);
}

#endif
