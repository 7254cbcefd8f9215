# The Assimp importer (FBX, Collada, 3DS, STL, ...): corpus inputs start with an extension line.
penumbra_fuzz_target(assimp LIBS penumbra_scene)
