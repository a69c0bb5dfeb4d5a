// Every input the fuzz targets ever found to break the NFF reader or its triangulation, kept in
// tests/fuzz/regressions/ with the answer the fixed code gives, and the fuzz seed corpus: read again
// in every test run. (How to fuzz: tests/fuzz/README.md.)
#include "tests/fuzz/nff_contract.hpp"
#include "tests/fuzz/polygon_contract.hpp"
#include "tests/grader/graded.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>

using namespace rt;

namespace {

std::string read_file(const std::filesystem::path& path)
{
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

// "ok" for a scene that keeps the contract, the message for a well-formed InputError, and what
// broke otherwise.
std::string nff_answer(const std::string& input)
{
    std::istringstream in(input);
    try {
        const std::string broken = nff_contract::scene_broken(parse_nff(in, "fuzz.nff"));
        return broken.empty() ? "ok" : "contract broken: " + broken;
    } catch (const InputError& e) {
        const std::string broken = nff_contract::message_broken(e.what(), "fuzz.nff", input);
        return broken.empty() ? e.what() : "contract broken: " + broken + ": " + e.what();
    }
}

// The same for an input of the polygon fuzz target: "ok", the message, or what broke.
std::string polygon_answer(const std::string& input)
{
    const auto vertices = polygon_contract::grid_outline(reinterpret_cast<const std::uint8_t*>(input.data()), input.size());
    try {
        const std::string broken = polygon_contract::broken(vertices, triangulate_polygon(vertices));
        return broken.empty() ? "ok" : "contract broken: " + broken;
    } catch (const InputError& e) {
        return e.what();
    }
}

std::vector<std::filesystem::path> files_in(const std::string& folder)
{
    std::vector<std::filesystem::path> files;
    for (const auto& entry : std::filesystem::directory_iterator(folder))
        if (entry.is_regular_file() && entry.path().extension() != ".expected" && entry.path().filename() != "README.md")
            files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    return files;
}

}  // namespace

TEST_CASE("every input the fuzzers found gets the answer the fixed reader gives", "[common]")
{
    // regressions/NAME holds the input, regressions/NAME.expected the answer: "ok" or the message.
    // NAME.polygon is an input of the polygon fuzz target; any other, an NFF file.
    for (const auto& input : files_in(std::string(RT_NFF_FUZZ_DIR) + "/regressions")) {
        INFO(input.filename().string());
        std::filesystem::path expected_path = input;
        expected_path += ".expected";
        REQUIRE(std::filesystem::exists(expected_path));
        std::string expected = read_file(expected_path);
        while (!expected.empty() && (expected.back() == '\n' || expected.back() == '\r'))
            expected.pop_back();
        const std::string text = read_file(input);
        CHECK((input.extension() == ".polygon" ? polygon_answer(text) : nff_answer(text)) == expected);
    }
}

TEST_CASE("every input of the NFF fuzz corpus keeps the reader's contract", "[common]")
{
    const auto corpus = files_in(std::string(RT_NFF_FUZZ_DIR) + "/corpus");
    CHECK(corpus.size() >= 10);
    for (const auto& input : corpus) {
        INFO(input.filename().string());
        CHECK(nff_answer(read_file(input)).rfind("contract broken", 0) == std::string::npos);
    }
}
