// The render side's contract for scene files, as a check shared by the fuzz target
// (scene_render_fuzz.cpp) and the normal test run (tests/scenes/scene_pictures_test.cpp, over the
// fuzz corpus): a scene the reader accepts renders in chapters 02, 03, 04 and 04's classic mode,
// 3 x 3 pixels through its own view, with no NaN or infinite pixel. Empty when it holds, else what
// broke.
#pragma once

#include "tests/scenes/scene_renders.hpp"

#include <string>

namespace rt::scene_render_contract {

inline std::string render_broken(const NffScene& nff)
{
    for (const scene_renders::Mode mode : scene_renders::modes) {
        const Image image = scene_renders::render_as(mode, scene_renders::small(nff, 3));
        if (const int bad = count_non_finite(image); bad > 0)
            return "chapter " + std::string(scene_renders::name(mode)) + ": " + std::to_string(bad) +
                   " of 9 pixels are NaN or infinite";
    }
    return "";
}

}  // namespace rt::scene_render_contract
