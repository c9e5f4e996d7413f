// Parses every scene of the POV-Ray 3.7 examples (povray-examples) when they are installed and
// prints how many load, and how many load without a warning. The lead's corpus test sets the
// expectations; this one only requires that no scene crashes or hangs the reader.
#include "io/pov/pov_test_util.h"

#include <algorithm>
#include <filesystem>
#include <iostream>

namespace sheaf::io::pov {
namespace {

TEST(PovCorpus, ParsesTheExampleScenes) {
    const std::filesystem::path root = "/usr/share/povray-3.7/scenes";
    if (!std::filesystem::is_directory(root)) GTEST_SKIP() << root << " is not installed";
    std::vector<std::string> scenes;
    for (const auto& e : std::filesystem::recursive_directory_iterator(
             root, std::filesystem::directory_options::follow_directory_symlink))
        if (e.path().extension() == ".pov") scenes.push_back(e.path().string());
    std::sort(scenes.begin(), scenes.end());
    // Scenes may #write files (HTML pages, include files) into the current folder: use a
    // temporary one.
    test::TempDir cwd;
    struct Restore {
        std::filesystem::path previous = std::filesystem::current_path();
        ~Restore() { std::filesystem::current_path(previous); }
    } restore;
    std::filesystem::current_path(cwd.path());
    size_t parsed = 0, clean = 0;
    for (const std::string& s : scenes) {
        try {
            const PovResult r = load_pov_scene(s, {});
            r.scene.validate();
            ++parsed;
            if (r.warnings.empty()) ++clean;
        } catch (const SceneError& e) {
            std::cout << "  " << e.what() << "\n";
        }
    }
    std::cout << "POV-Ray examples: " << scenes.size() << " scenes, " << parsed << " parsed, "
              << clean << " usable without warnings\n";
    EXPECT_GT(scenes.size(), 0u);
}

} // namespace
} // namespace sheaf::io::pov
