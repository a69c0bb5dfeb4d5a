// The kit's NFF scenes as chapters 02, 03, 04 and 04's classic mode render them from a file, against
// their reference pictures: the file's view, objects, materials and lights must arrive in each
// chapter as they did when the references were made and looked at (scene_pictures.hpp). And the
// render fuzzer's contract (no NaN pixel, tests/fuzz/scene_render_contract.hpp) over its corpus,
// so every run checks it without clang.
#include "tests/fuzz/scene_render_contract.hpp"
#include "tests/grader/graded.hpp"
#include "tests/grader/picture.hpp"
#include "tests/scenes/scene_pictures.hpp"

#include <filesystem>
#include <fstream>

using namespace rt;

TEST_CASE("the kit's NFF scenes render in chapters 02 to 04 as their reference pictures show", "[scenes]")
{
    for (const pictures::ScenePicture& picture : pictures::scene_pictures()) {
        const grader::PictureVerdict verdict = grader::compare_with_reference(picture.render(), picture.name);
        INFO(picture.name << " at " << pictures::scene_side << "x" << pictures::scene_side << ": " << verdict.report);
        CHECK(verdict.matches);
    }
}

TEST_CASE("every scene the reader accepts among the fuzz corpus and the kit's scenes renders with no NaN pixel", "[scenes]")
{
    namespace fs = std::filesystem;
    int rendered = 0;
    for (const char* dir : {RT_NFF_FUZZ_DIR "/corpus", RT_NFF_FUZZ_DIR "/regressions", RT_NFF_SCENES_DIR}) {
        for (const fs::directory_entry& entry : fs::directory_iterator(dir)) {
            const std::string name = entry.path().filename().string();
            if (name.find('.') != std::string::npos && entry.path().extension() != ".nff")
                continue;  // a regression's .expected answer, a polygon outline, a README
            std::ifstream in(entry.path(), std::ios::binary);
            NffScene nff;
            try {
                nff = parse_nff(in, "fuzz.nff");
            } catch (const InputError&) {
                continue;  // refused: the reader's tests check how
            }
            const std::string broken = scene_render_contract::render_broken(nff);
            INFO(entry.path().string() << ": " << broken);
            CHECK(broken.empty());
            ++rendered;
        }
    }
    INFO(rendered << " scenes rendered");
    CHECK(rendered >= 10);
}
