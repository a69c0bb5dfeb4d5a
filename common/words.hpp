// A list said as a sentence says it: "07.1, 07.3 and 07.4", "'hither' or 'resolution'", or a plain
// "07.1 07.3" to be read back word by word. The kit's one list joiner.
#pragma once

#include <string>
#include <vector>

namespace rt {

// The words with `between` between them, except the last two, which get `last`: ({"a", "b", "c"},
// ", ", " and ") is "a, b and c". Empty for no words.
inline std::string join_words(const std::vector<std::string>& words, const std::string& between, const std::string& last)
{
    std::string out;
    for (std::size_t k = 0; k < words.size(); ++k)
        out += (k == 0 ? "" : k + 1 == words.size() ? last : between) + words[k];
    return out;
}

inline std::string join_words(const std::vector<std::string>& words, const std::string& between)
{
    return join_words(words, between, between);
}

}  // namespace rt
