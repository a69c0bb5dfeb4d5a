// A chapter's picture test: its figure, small, rendered by the code under test, against the
// reference PNG rendered from the solutions (tests/references/, the `references` target).
//
//   PICTURE_TEST("07", "the fractal mountain through the grid", "07_uniform_grid", pictures::ch07(),
//                "chapter 07's figure at 96x54, 1 sample per pixel")
//
// is the graded case 07.P, 3 points, named "the figure (the fractal mountain through the grid)
// matches the reference picture".
#pragma once

#include "tests/grader/graded.hpp"
#include "tests/grader/picture.hpp"

#include <string>

namespace rt::grader {

inline void check_reference_picture(const Image& image, const std::string& name, const std::string& what)
{
    const PictureVerdict verdict = compare_with_reference(image, name);
    INFO(what << ": " << verdict.report);
    CHECK(verdict.matches);
}

}  // namespace rt::grader

#define PICTURE_TEST(number, figure, name, image, what)                                   \
    GRADED_TEST("the figure (" figure ") matches the reference picture", number ".P", 3) \
    {                                                                                     \
        rt::grader::check_reference_picture(image, name, what);                           \
    }
