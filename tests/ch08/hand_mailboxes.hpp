// Mailboxes for chapter 07's hand grid (tests/ch07/hand_grid.hpp): one for each of its objects, all
// empty, and no signature handed out yet.
#pragma once

#include "08_mailboxing/08_mailboxing.hpp"
#include "tests/ch07/hand_grid.hpp"

#include <vector>

namespace rt::grader::hand_grid {

inline Mailboxes fresh_mailboxes() { return Mailboxes{std::vector<Mailbox>(objects().size()), 0}; }

}  // namespace rt::grader::hand_grid
