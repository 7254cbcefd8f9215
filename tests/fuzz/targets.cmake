# OBJ (+MTL after the first NUL byte) and glTF/GLB importers.
penumbra_fuzz_target(obj LIBS penumbra_scene)
penumbra_fuzz_target(gltf LIBS penumbra_scene)
# Render checkpoints (penumbra render --resume).
penumbra_fuzz_target(checkpoint LIBS penumbra_render)
