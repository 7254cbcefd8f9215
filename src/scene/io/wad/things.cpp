#include "scene/io/wad/things.h"

namespace penumbra::wad {
namespace {

// {type, sprite, frame, full bright, hang height}, from each type's spawn state in the game.
constexpr ThingType kThings[] = {
    {3004, "POSS", 'A', false, 0}, {9, "SPOS", 'A', false, 0},    {64, "VILE", 'A', false, 0},
    {66, "SKEL", 'A', false, 0},   {67, "FATT", 'A', false, 0},   {65, "CPOS", 'A', false, 0},
    {3001, "TROO", 'A', false, 0}, {3002, "SARG", 'A', false, 0}, {58, "SARG", 'A', false, 0},
    {3005, "HEAD", 'A', false, 0}, {3003, "BOSS", 'A', false, 0}, {69, "BOS2", 'A', false, 0},
    {3006, "SKUL", 'A', true, 0},  {7, "SPID", 'A', false, 0},    {68, "BSPI", 'A', false, 0},
    {16, "CYBR", 'A', false, 0},   {71, "PAIN", 'A', false, 0},   {84, "SSWV", 'A', false, 0},
    {72, "KEEN", 'A', false, 72},  {88, "BBRN", 'A', false, 0},   {2035, "BAR1", 'A', false, 0},
    {2018, "ARM1", 'A', false, 0}, {2019, "ARM2", 'A', false, 0}, {2014, "BON1", 'A', false, 0},
    {2015, "BON2", 'A', false, 0}, {5, "BKEY", 'A', false, 0},    {13, "RKEY", 'A', false, 0},
    {6, "YKEY", 'A', false, 0},    {39, "YSKU", 'A', false, 0},   {38, "RSKU", 'A', false, 0},
    {40, "BSKU", 'A', false, 0},   {2011, "STIM", 'A', false, 0}, {2012, "MEDI", 'A', false, 0},
    {2013, "SOUL", 'A', true, 0},  {2022, "PINV", 'A', true, 0},  {2023, "PSTR", 'A', true, 0},
    {2024, "PINS", 'A', true, 0},  {2025, "SUIT", 'A', true, 0},  {2026, "PMAP", 'A', true, 0},
    {2045, "PVIS", 'A', true, 0},  {83, "MEGA", 'A', true, 0},    {2007, "CLIP", 'A', false, 0},
    {2048, "AMMO", 'A', false, 0}, {2010, "ROCK", 'A', false, 0}, {2046, "BROK", 'A', false, 0},
    {2047, "CELL", 'A', false, 0}, {17, "CELP", 'A', false, 0},   {2008, "SHEL", 'A', false, 0},
    {2049, "SBOX", 'A', false, 0}, {8, "BPAK", 'A', false, 0},    {2006, "BFUG", 'A', false, 0},
    {2002, "MGUN", 'A', false, 0}, {2005, "CSAW", 'A', false, 0}, {2003, "LAUN", 'A', false, 0},
    {2004, "PLAS", 'A', false, 0}, {2001, "SHOT", 'A', false, 0}, {82, "SGN2", 'A', false, 0},
    {85, "TLMP", 'A', true, 0},    {86, "TLP2", 'A', true, 0},    {2028, "COLU", 'A', true, 0},
    {30, "COL1", 'A', false, 0},   {31, "COL2", 'A', false, 0},   {32, "COL3", 'A', false, 0},
    {33, "COL4", 'A', false, 0},   {37, "COL6", 'A', false, 0},   {36, "COL5", 'A', false, 0},
    {41, "CEYE", 'A', true, 0},    {42, "FSKU", 'A', true, 0},    {43, "TRE1", 'A', false, 0},
    {44, "TBLU", 'A', true, 0},    {45, "TGRN", 'A', true, 0},    {46, "TRED", 'A', true, 0},
    {55, "SMBT", 'A', true, 0},    {56, "SMGT", 'A', true, 0},    {57, "SMRT", 'A', true, 0},
    {47, "SMIT", 'A', false, 0},   {48, "ELEC", 'A', false, 0},   {34, "CAND", 'A', true, 0},
    {35, "CBRA", 'A', true, 0},    {49, "GOR1", 'A', false, 68},  {50, "GOR2", 'A', false, 84},
    {51, "GOR3", 'A', false, 84},  {52, "GOR4", 'A', false, 68},  {53, "GOR5", 'A', false, 52},
    {59, "GOR2", 'A', false, 84},  {60, "GOR4", 'A', false, 68},  {61, "GOR3", 'A', false, 52},
    {62, "GOR5", 'A', false, 52},  {63, "GOR1", 'A', false, 68},  {22, "HEAD", 'L', false, 0},
    {15, "PLAY", 'N', false, 0},   {18, "POSS", 'L', false, 0},   {21, "SARG", 'N', false, 0},
    {23, "SKUL", 'K', false, 0},   {20, "TROO", 'M', false, 0},   {19, "SPOS", 'L', false, 0},
    {10, "PLAY", 'W', false, 0},   {12, "PLAY", 'W', false, 0},   {28, "POL2", 'A', false, 0},
    {24, "POL5", 'A', false, 0},   {27, "POL4", 'A', false, 0},   {29, "POL3", 'A', true, 0},
    {25, "POL1", 'A', false, 0},   {26, "POL6", 'A', false, 0},   {54, "TRE2", 'A', false, 0},
    {70, "FCAN", 'A', true, 0},    {73, "HDB1", 'A', false, 88},  {74, "HDB2", 'A', false, 88},
    {75, "HDB3", 'A', false, 64},  {76, "HDB4", 'A', false, 64},  {77, "HDB5", 'A', false, 64},
    {78, "HDB6", 'A', false, 64},  {79, "POB1", 'A', false, 0},   {80, "POB2", 'A', false, 0},
    {81, "BRS1", 'A', false, 0},
};

}  // namespace

const ThingType* thingType(std::uint16_t type) {
    for (const ThingType& t : kThings)
        if (t.type == type) return &t;
    return nullptr;
}

}  // namespace penumbra::wad
