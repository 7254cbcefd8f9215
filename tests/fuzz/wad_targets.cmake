penumbra_fuzz_target(wad LIBS penumbra_scene)
