// Random numbers: a PCG hash to seed each path from (seed, sample, pixel), then a PCG stream
// (RXS-M-XS output) to draw from. Deterministic for a given seed on a given device.
#ifndef PN_RNG_GLSL
#define PN_RNG_GLSL

uint pcgHash(uint v) {
    uint state = v * 747796405u + 2891336453u;
    uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return (word >> 22u) ^ word;
}

uint rngSeed(uint pixelIndex, uint sampleIndex, uint seed) {
    return pcgHash(pixelIndex ^ pcgHash(sampleIndex ^ pcgHash(seed)));
}

uint rngNextUint(inout uint state) {
    state = state * 747796405u + 2891336453u;
    uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return (word >> 22u) ^ word;
}

// Uniform in [0, 1): the top 24 bits, so 1.0 is never returned.
float rngNext(inout uint state) { return float(rngNextUint(state) >> 8) * (1.0 / 16777216.0); }

// The sampleIndex-th point of a rotated golden-ratio (R1) sequence in [0, 1): samples of one
// pixel and dimension are spread evenly instead of independently, so their mean converges faster;
// each one is still uniform, its rotation coming from a hash of (pixel, dimension, seed).
float stratifiedSample(uint pixelIndex, uint dimension, uint sampleIndex, uint seed) {
    uint rotation = pcgHash(pixelIndex ^ pcgHash(dimension ^ pcgHash(seed ^ 0x9e3779b9u)));
    return float((rotation + sampleIndex * 2654435769u) >> 8) * (1.0 / 16777216.0);
}

vec2 rngNext2(inout uint state) {
    float a = rngNext(state);
    return vec2(a, rngNext(state));
}

#endif
