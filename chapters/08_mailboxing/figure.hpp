// Chapter 08's figure: a pile of long thin sticks, each across many grid cells, rendered through
// the grid with mailboxes, beside a heat map of the tests the mailboxes answered per pixel: the
// tests a grid without them would have repeated.
#pragma once

#include "07_uniform_grid/figure.hpp"
#include "08_mailboxing/mailbox_grid.hpp"

#include <memory>
#include <string>

namespace rt::ch08 {

constexpr int figure_sticks_depth = 5;  // 8000 sticks

inline NffScene figure_scene() { return generated_scene(write_sticks, figure_sticks_depth, "sticks, depth 5"); }

// Chapter 07's structures and the grid with mailboxes (programs/structures.hpp): a mailbox per object
// and thread, or with --mailbox cache your ray cache of 1 KB a thread (08.4, RayCacheGrid).
inline Structures structures()
{
    return followed_by(ch07::structures(),
                       {{"grid-mailbox", "the uniform grid with a mailbox per object and thread", 8,
                         ch07::default_lambda, {"--lambda", "--mailbox"},
                         [](const Objects& o, const StructureTuning& t) -> std::unique_ptr<Accelerator> {
                             if (t.mailbox == "cache")
                                 return std::make_unique<RayCacheGrid>(o, t.lambda);  // your 08.4
                             return std::make_unique<MailboxGrid>(o, t.lambda);
                         }}});
}

// The figure's scene through the grid with mailboxes; with `cost`, what each pixel cost.
inline Image render_through_mailboxes(const RenderSettings& settings, float lambda = ch07::default_lambda,
                                      CostMap* cost = nullptr)
{
    return render_figure_through(figure_scene(), settings,
                                       [&](const Objects& o) { return std::make_unique<MailboxGrid>(o, lambda); }, cost);
}

}  // namespace rt::ch08
