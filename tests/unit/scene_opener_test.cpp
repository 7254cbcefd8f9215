// The viewer's Open button: a scene that cannot be opened is one line of text, never a throw.
#include <gtest/gtest.h>

#include "app/scene_opener.h"

namespace penumbra::app {
namespace {

TEST(SceneOpener, AMissingFileIsOneLineNamingIt) {
    const std::string path = "/no/such/dir/scene.obj";
    OpenedScene opened = openSceneFile(path);
    EXPECT_FALSE(opened.scene.has_value());
    ASSERT_FALSE(opened.error.empty());
    EXPECT_EQ(opened.error.find('\n'), std::string::npos) << opened.error;
    EXPECT_NE(opened.error.find(path), std::string::npos) << opened.error;
}

TEST(SceneOpener, AnEmptyPathIsAnError) {
    OpenedScene opened = openSceneFile("   ");
    EXPECT_FALSE(opened.scene.has_value());
    EXPECT_EQ(opened.error, "no scene file given");
}

TEST(SceneOpener, ABuiltInSceneOpensWithSurroundingSpaceTrimmed) {
    OpenedScene opened = openSceneFile(" cornell ");
    ASSERT_TRUE(opened.scene.has_value()) << opened.error;
    EXPECT_TRUE(opened.error.empty());
    EXPECT_GT(opened.scene->triangleCount(), 0u);
}

}  // namespace
}  // namespace penumbra::app
