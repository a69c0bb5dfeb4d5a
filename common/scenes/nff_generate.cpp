// nff_generate: writes one of the kit's procedural NFF scenes to standard output.
//
//   nff_generate sphereflake --depth 4 > sphereflake4.nff
//
// Bad arguments are answered like the chapter programs': one line on stderr, exit status 2.
#include "common/cli.hpp"
#include "common/scenes/nff_generators.hpp"

#include <iostream>

using namespace rt;

namespace {

std::string scene_names()
{
    std::string names;
    for (const NffGenerator& g : nff_generators())
        names += (names.empty() ? "" : ", ") + g.name;
    return names;
}

void print_usage(std::ostream& out)
{
    out << "usage: nff_generate SCENE [--depth N] > scene.nff\n"
           "Writes one of the kit's procedural NFF scenes to standard output.\n\nscenes:\n";
    for (const NffGenerator& g : nff_generators())
        out << "  " << g.name << " (depth 0 to " << g.max_depth << ", default " << g.default_depth
            << "): " << g.summary << '\n';
    out << "\nnff_generate SCENE --help lists the scene's options.\n";
}

}  // namespace

int main(int argc, char** argv)
{
    return run_program("nff_generate", [&] {
        if (argc < 2)
            throw InputError("which scene? " + scene_names() + " (try --help)");
        const std::string name = argv[1];
        if (name == "--help" || name == "-h") {
            print_usage(std::cout);
            return 0;
        }
        const NffGenerator* generator = nullptr;
        for (const NffGenerator& g : nff_generators())
            if (g.name == name)
                generator = &g;
        if (!generator)
            throw InputError("unknown scene '" + name + "' (" + scene_names() + ")");

        int depth = generator->default_depth;
        CommandLine cli("nff_generate " + name, generator->summary);
        cli.option("--depth", depth, "levels of recursion", 0, generator->max_depth);
        // The scene's name stands where a program's name would: the options start after it.
        if (!cli.parse(argc - 1, argv + 1, std::cout))
            return 0;
        generator->write(std::cout, depth);
        std::cout.flush();
        if (!std::cout)
            throw InputError("cannot write the scene to standard output");
        return 0;
    });
}
