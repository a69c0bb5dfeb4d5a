// An exercise's stub says that it ran: a program rendered from unfinished exercises then tells the
// student which ones its picture still takes from stubs, instead of showing a flat picture with no
// word (write_figure prints the list).
#pragma once

#include <string>
#include <vector>

namespace rt {

// Records that the stub of exercise `exercise` ("NN.k") ran. Cheap enough for a stub called per
// ray: one relaxed atomic load once the exercise is recorded.
void note_stub(const char* exercise);

// The stub's harmless answer, recorded: `return stub("01.2", std::nullopt);`. A student replaces
// the whole line with their answer, and the exercise is no longer counted.
template <class T>
T stub(const char* exercise, T harmless)
{
    note_stub(exercise);
    return harmless;
}

// The exercises whose stubs ran in this process, in order ("01.1", "01.3", ...).
std::vector<std::string> stubs_that_ran();

// Forgets which stubs ran: the grader asks again for each graded case.
void forget_stubs();

}  // namespace rt
