// The small picture that chapter 08's picture test renders, shared with make_references: the
// figure's sticks through your grid with mailboxes (the render alone).
#pragma once

#include "08_mailboxing/figure.hpp"

namespace rt::pictures {

inline Image ch08() { return ch08::render_through_mailboxes(quiet_render(96, 54, 1)); }

}  // namespace rt::pictures
