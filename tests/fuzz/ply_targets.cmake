# The PLY importer (ASCII, binary, gzip).
penumbra_fuzz_target(ply LIBS penumbra_scene)
