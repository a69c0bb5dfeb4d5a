// The registry of structures: every structure that can answer a scene's queries, one entry each.
// An entry says the structure's name (the one spelling --accel, the benchmark, the tests and the
// fuzzer use), what it is, which chapter brings it, the options that shape it, and how it is built
// from the object list.
//
// A chapter's program links chapters 01..N only, so the registry grows chapter by chapter: each
// chapter from 07 on lists its own entries after the previous chapter's, in its figure.hpp's
// `structures()`. Chapter 07's program sees brute force and the grid; chapter 10's list holds every
// structure, and the benchmark, tests/structures/legal_scenes_test.cpp and tests/fuzz/accel_fuzz.cpp
// walk it. Adding a structure is one entry in its chapter's list, beside its own code.
#pragma once

#include "02_spheres_triangles/scene_query.hpp"
#include "common/cli.hpp"

#include <algorithm>
#include <cstdint>
#include <functional>
#include <initializer_list>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace rt {

// What a program's options may set. A field left at its default keeps the structure's own choice;
// each structure reads only the fields its options (Structure::options) name.
struct StructureTuning {
    float lambda = 0.0f;           // --lambda, cells per object; 0: the structure's default_lambda
    int leaf_size = 0;             // --leaf-size; 0: the structure's own
    int max_depth = -1;            // --max-depth; -1: the structure's own
    std::string split;             // --split, "sah", "median" or "open"; empty: the structure's own
    std::uint32_t table_size = 0;  // --table-size, a hash table's size; 0: the structure's own
    std::string table_hash;        // --table-hash, "mod" or "open" (09.6); empty: the structure's own
    std::string mailbox;           // --mailbox, "object" or "cache" (08.4); empty: the structure's own
    std::string resolution;        // --resolution, "rule" or "open" (07.7); empty: the structure's own
};

// The tuning of a grid at `lambda` cells per object, every other field left to the structure.
inline StructureTuning at_density(float lambda)
{
    StructureTuning t;
    t.lambda = lambda;
    return t;
}

// One structure. Its name must be one word: lowercase letters and digits, joined by hyphens.
struct Structure {
    std::string name;  // one word: --accel's value, the benchmark's column, the tests' name
    std::string what;  // a few words for --help
    int chapter;       // the chapter that brings it: a chapter's program lists only its own and earlier
    float default_lambda;              // cells per object when --lambda is not given; 0: not a grid
    std::vector<std::string> options;  // the options that shape it ("--lambda", "--leaf-size", ...)
    std::function<std::unique_ptr<Accelerator>(const Objects&, const StructureTuning&)> build;  // see make

    // Built over `objects`, with the tuning's lambda, or default_lambda when it gives none; nullptr
    // for brute force, which needs nothing built (a scene without an accelerator asks brute_force()).
    std::unique_ptr<Accelerator> make(const Objects& objects, StructureTuning tuning = {}) const
    {
        if (tuning.lambda <= 0.0f)
            tuning.lambda = default_lambda;
        return build(objects, tuning);
    }

    bool takes(const std::string& option) const
    {
        for (const std::string& o : options)
            if (o == option)
                return true;
        return false;
    }
};

using Structures = std::vector<Structure>;

// The name of the reference every other structure is held to: the slides' test of every object.
inline const std::string brute_force_name = "brute";

// What the tests and the fuzzer hold to brute force: every structure of the list but brute force.
inline Structures beside_brute_force(const Structures& list)
{
    Structures others;
    for (const Structure& s : list)
        if (s.name != brute_force_name)
            others.push_back(s);
    return others;
}

// A chapter's list: the earlier chapters' entries, then its own.
inline Structures followed_by(Structures earlier, std::initializer_list<Structure> own)
{
    earlier.insert(earlier.end(), own.begin(), own.end());
    return earlier;
}

// Names in words: "a", "a or b", "a, b or c".
inline std::string one_of(const std::vector<std::string>& names)
{
    std::string text;
    for (std::size_t k = 0; k < names.size(); ++k)
        text += (k == 0 ? "" : k + 1 == names.size() ? " or " : ", ") + names[k];
    return text;
}

// "a, b or c": the names of the structures that pass `keep`, for help and messages.
inline std::string structure_names(
    const Structures& list, const std::function<bool(const Structure&)>& keep = [](const Structure&) { return true; })
{
    std::vector<std::string> names;
    for (const Structure& s : list)
        if (keep(s))
            names.push_back(s.name);
    return one_of(names);
}

// A word option that takes one of `choices` (--mailbox, --table-hash, --split): when given anything
// else, the program stops with "--split takes sah, median or open, got 'x'".
inline void check_choice(const CommandLine& cli, const std::string& name, const std::string& value,
                         const std::vector<std::string>& choices)
{
    if (cli.given(name) && std::find(choices.begin(), choices.end(), value) == choices.end())
        throw InputError(name + " takes " + one_of(choices) + ", got '" + value + "'");
}

// The entry called `name`; an unknown name is bad input, answered with the names there are.
inline const Structure& structure_named(const Structures& list, const std::string& name)
{
    for (const Structure& s : list)
        if (s.name == name)
            return s;
    throw InputError("--accel takes " + structure_names(list) + ", got '" + name + "'");
}

// --accel's help: every structure of the list, with the chapter that brings it and what it is.
inline std::string accel_help(const Structures& list)
{
    std::string text = "what answers the queries:";
    for (std::size_t k = 0; k < list.size(); ++k)
        text += (k == 0 ? " " : "; ") + list[k].name + " (chapter " + (list[k].chapter < 10 ? "0" : "") +
                std::to_string(list[k].chapter) + ": " + list[k].what + ")";
    return text;
}

// --lambda's help: the structures it shapes, each with its default.
inline std::string lambda_help(const Structures& list)
{
    std::string text = "cells per object, for";
    const char* between = " ";
    for (const Structure& s : list)
        if (s.takes("--lambda")) {
            std::ostringstream value;
            value << s.default_lambda;
            text += between + s.name + " (default " + value.str() + ")";
            between = ", ";
        }
    return text;
}

// An option that shapes some structures of the list, given with one it does not shape, is bad input:
// the message names the structures it applies to.
inline void check_structure_options(const Structures& list, const Structure& chosen, const CommandLine& cli)
{
    for (const Structure& s : list)
        for (const std::string& option : s.options)
            if (cli.given(option) && !chosen.takes(option))
                throw InputError(option + " shapes " +
                                 structure_names(list, [&](const Structure& t) { return t.takes(option); }) +
                                 "; it does not apply to --accel " + chosen.name);
}

// What a program's --accel and --lambda choose from its chapter's list, with what its other options
// set in `tuning`: the structure the program builds for a scene.
struct StructureChoice {
    Structures list;
    std::string accel;
    StructureTuning tuning = {};

    // --accel and --lambda, their help from the list; a density above `most_lambda` is bad input.
    void add_options(CommandLine& cli, float most_lambda)
    {
        cli.option("--accel", accel, accel_help(list));
        cli.option("--lambda", tuning.lambda, lambda_help(list), 0.0f, most_lambda);
    }

    // After the parse: the structure named, with every option given one that it takes.
    const Structure& chosen(const CommandLine& cli) const
    {
        const Structure& s = structure_named(list, accel);
        check_structure_options(list, s, cli);
        return s;
    }

    std::unique_ptr<Accelerator> make(const Objects& objects) const
    {
        return structure_named(list, accel).make(objects, tuning);
    }
};

}  // namespace rt
