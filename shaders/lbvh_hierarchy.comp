#version 460
// GPU BVH build, step 4: the binary radix tree over the sorted codes, every interior node at once
// (Karras 2012, "Maximizing parallelism in the construction of BVHs, octrees and k-d trees",
// section 4 and its Figure 4). Interior node i covers a range of sorted keys with i at one end;
// the direction is where the neighbour shares the longer prefix, the other end is found by an
// exponential then a binary search, and the split is where the range's common prefix ends.
// Equal codes are told apart by their positions (the prefix of code then index), so duplicates
// still give a tree of depth about log2 of their number.
#extension GL_GOOGLE_include_directive : require

#include "lib/lbvh.glsl"

int pnLeadingZeros(uint x) { return 31 - findMSB(x); }  // findMSB(0) = -1: 32

// The length of the common prefix of keys i and j as (code, index); -1 outside the keys.
int delta(int i, int j) {
    if (j < 0 || j >= int(push.count)) return -1;
    uint a = keysA[i], b = keysA[j];
    if (a == b) return 32 + pnLeadingZeros(uint(i ^ j));
    return pnLeadingZeros(a ^ b);
}

void main() {
    int i = int(gl_GlobalInvocationID.x), n = int(push.count);
    if (i >= n - 1) return;
    int d = delta(i, i + 1) > delta(i, i - 1) ? 1 : -1;
    int minPrefix = delta(i, i - d);
    int span = 2;
    while (delta(i, i + span * d) > minPrefix) span *= 2;
    int length = 0;
    for (int t = span / 2; t >= 1; t /= 2)
        if (delta(i, i + (length + t) * d) > minPrefix) length += t;
    int j = i + length * d;
    int nodePrefix = delta(i, j);
    int s = 0, step = length;
    do {
        step = (step + 1) / 2;
        if (delta(i, i + (s + step) * d) > nodePrefix) s += step;
    } while (step > 1);
    int split = i + s * d + min(d, 0);
    int first = min(i, j), last = max(i, j);
    // A child covering one key is a leaf (stored after the n - 1 interior nodes).
    uint left = first == split ? uint(n - 1 + split) : uint(split);
    uint right = last == split + 1 ? uint(n - 1 + split + 1) : uint(split + 1);
    nodes[i].left = left;
    nodes[i].right = right;
    nodes[i].first = uint(first);
    nodes[i].leaves = uint(last - first + 1);
    donePass[i] = 0u;
    nodes[left].parent = uint(i);
    nodes[right].parent = uint(i);
    if (i == 0) nodes[0].parent = PN_LBVH_NONE;
}
