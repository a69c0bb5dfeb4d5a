// The kit's NFF scenes as chapters 02, 03, 04 and 04's classic mode render them from a file, against
// their reference pictures: the file's view, objects, materials and lights must arrive in each
// chapter as they did when the references were made and looked at (scene_pictures.hpp).
#include "tests/grader/graded.hpp"
#include "tests/grader/picture.hpp"
#include "tests/scenes/scene_pictures.hpp"

using namespace rt;

TEST_CASE("the kit's NFF scenes render in chapters 02 to 04 as their reference pictures show", "[scenes]")
{
    for (const pictures::ScenePicture& picture : pictures::scene_pictures()) {
        const grader::PictureVerdict verdict = grader::compare_with_reference(picture.render(), picture.name);
        INFO(picture.name << " at " << pictures::scene_side << "x" << pictures::scene_side << ": " << verdict.report);
        CHECK(verdict.matches);
    }
}
