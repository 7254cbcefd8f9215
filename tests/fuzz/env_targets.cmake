# Environment maps: Radiance .hdr and OpenEXR .exr.
penumbra_fuzz_target(env LIBS penumbra_scene)
