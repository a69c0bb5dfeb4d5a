// The path of one ray (chapters/programs/README.md), drawn: each file a box, in a column for its
// folder, each hop an arrow numbered as the list numbers it, the student's exercises marked. The
// drawing is made from the README's own numbered list, so it cannot drift from it.
//
//   trip_map write README.md MAP.svg : draws the list into MAP.svg
//   trip_map check README.md MAP.svg : exit 1 when MAP.svg is not what the list draws now
//
// A hop is a line `N. [`path`](link):`function`...`; the first file it links is the hop's file. A
// hop whose text says (EXERCISE NN.k) is the student's: its box is marked with the tag.
#include <algorithm>
#include <cmath>
#include <fstream>
#include <iostream>
#include <map>
#include <utility>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace {

struct Hop {
    int number = 0;
    std::string file, function, exercise;  // exercise: "EXERCISE 01.1", or empty
};

std::vector<Hop> hops_of(const std::string& readme)
{
    std::ifstream in(readme);
    if (!in)
        throw std::runtime_error(readme + ": cannot be read");
    const std::regex item(R"(^(\d+)\. \[`([^`]+)`\]\([^)]*\):`([^`]+)`.*)");
    const std::regex tag(R"(EXERCISE\s+(\d\d\.\d+))");
    std::vector<Hop> hops;
    std::string text;  // the current item's text, its lines joined
    const auto close_item = [&] {
        std::smatch m;
        if (!hops.empty() && std::regex_search(text, m, tag))
            hops.back().exercise = "EXERCISE " + m[1].str();
        text.clear();
    };
    for (std::string line; std::getline(in, line);) {
        std::smatch m;
        if (std::regex_match(line, m, item)) {
            close_item();
            hops.push_back({std::stoi(m[1].str()), m[2].str(), m[3].str(), ""});
            text = line;
        } else if (!hops.empty() && !line.empty() && line.front() == ' ') {
            text += " " + line;
        } else {
            close_item();
        }
    }
    close_item();
    for (std::size_t k = 0; k < hops.size(); ++k)
        if (hops[k].number != static_cast<int>(k) + 1)
            throw std::runtime_error(readme + ": hop " + std::to_string(hops[k].number) + " follows hop " +
                                     std::to_string(k) + ": the list must number its hops 1, 2, 3, ...");
    if (hops.empty())
        throw std::runtime_error(readme + ": no numbered hop ('1. [`file`](link):`function`: ...')");
    return hops;
}

std::string folder_of(const std::string& file) { return file.substr(0, file.rfind('/') + 1); }
std::string name_of(const std::string& file) { return file.substr(file.rfind('/') + 1); }

std::string escaped(const std::string& s)
{
    std::string out;
    for (const char c : s)
        out += c == '&' ? "&amp;" : c == '<' ? "&lt;" : c == '>' ? "&gt;" : std::string(1, c);
    return out;
}

// The drawing: folders as columns in the order the ray first enters them, each file a box in its
// folder's column in the order the ray first meets it.
std::string svg_of(const std::vector<Hop>& hops)
{
    std::vector<std::string> folders, files;
    for (const Hop& h : hops) {
        if (std::find(folders.begin(), folders.end(), folder_of(h.file)) == folders.end())
            folders.push_back(folder_of(h.file));
        if (std::find(files.begin(), files.end(), h.file) == files.end())
            files.push_back(h.file);
    }
    // Why these sizes: a column fits the longest file name at 13 px (about 7.5 px a character), a
    // row fits a name and an exercise's tag, and the gap between columns leaves the arrows room.
    const int column_width = 250, box_width = 200, box_height = 44, row_height = 64, top = 70, left = 20;
    std::map<std::string, int> column_of, row_of;
    std::map<std::string, std::string> exercise_of;
    std::vector<int> rows(folders.size(), 0);
    for (const std::string& f : files) {
        const int c = static_cast<int>(std::find(folders.begin(), folders.end(), folder_of(f)) - folders.begin());
        column_of[f] = c;
        row_of[f] = rows[static_cast<std::size_t>(c)]++;
    }
    for (const Hop& h : hops)
        if (!h.exercise.empty())
            exercise_of[h.file] += (exercise_of[h.file].empty() ? "" : ", ") + h.exercise.substr(9);
    const int most_rows = *std::max_element(rows.begin(), rows.end());
    const int width = left * 2 + static_cast<int>(folders.size()) * column_width - (column_width - box_width);
    const int height = top + most_rows * row_height + 40;
    const auto box_x = [&](const std::string& f) { return left + column_of[f] * column_width; };
    const auto box_y = [&](const std::string& f) { return top + row_of[f] * row_height; };

    std::ostringstream svg;
    svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << height
        << "\" viewBox=\"0 0 " << width << ' ' << height << "\" font-family=\"sans-serif\">\n"
        << "<!-- Drawn by tests/lessons/trip_map.cpp from the numbered list of chapters/programs/README.md: "
           "edit the list, then build the target trip_map_refresh. -->\n"
        << "<defs><marker id=\"head\" viewBox=\"0 0 10 10\" refX=\"9\" refY=\"5\" markerWidth=\"7\" "
           "markerHeight=\"7\" orient=\"auto-start-reverse\"><path d=\"M 0 0 L 10 5 L 0 10 z\" fill=\"#c0392b\"/>"
           "</marker></defs>\n"
        << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
        << "<text x=\"" << left << "\" y=\"22\" font-size=\"15\" font-weight=\"bold\">One primary ray of chapter "
           "10's program: "
        << hops.size() << " hops, " << files.size() << " files named by the hops, " << folders.size()
        << " folders; a yellow box is the student's exercise</text>\n";
    for (std::size_t c = 0; c < folders.size(); ++c)
        svg << "<text x=\"" << left + static_cast<int>(c) * column_width << "\" y=\"52\" font-size=\"12\" "
            << "fill=\"#555\">" << escaped(folders[c]) << "</text>\n";
    for (const std::string& f : files) {
        const bool exercise = exercise_of.count(f) > 0;
        svg << "<rect x=\"" << box_x(f) << "\" y=\"" << box_y(f) << "\" width=\"" << box_width << "\" height=\""
            << box_height << "\" rx=\"6\" fill=\"" << (exercise ? "#ffe08a" : "#eef3f8") << "\" stroke=\""
            << (exercise ? "#b8860b" : "#6b7f95") << "\" stroke-width=\"" << (exercise ? 2 : 1) << "\"/>\n"
            << "<text x=\"" << box_x(f) + 8 << "\" y=\"" << box_y(f) + (exercise ? 18 : 27) << "\" font-size=\"13\">"
            << escaped(name_of(f)) << "</text>\n";
        if (exercise)
            svg << "<text x=\"" << box_x(f) + 8 << "\" y=\"" << box_y(f) + 35 << "\" font-size=\"11\" "
                << "fill=\"#7a5a00\">EXERCISE " << escaped(exercise_of[f]) << "</text>\n";
    }
    // Each hop from its file's box to the next hop's, bowed to one side so that a hop and its
    // return stay apart; its number at its middle. A hop within one file has no arrow.
    for (std::size_t k = 0; k + 1 < hops.size(); ++k) {
        const std::string& a = hops[k].file;
        const std::string& b = hops[k + 1].file;
        if (a == b)
            continue;
        const double acx = box_x(a) + box_width / 2.0, acy = box_y(a) + box_height / 2.0;
        const double bcx = box_x(b) + box_width / 2.0, bcy = box_y(b) + box_height / 2.0;
        const double mx = (acx + bcx) / 2.0, my = (acy + bcy) / 2.0;
        const double dx = bcx - acx, dy = bcy - acy, length = std::max(1.0, std::hypot(dx, dy));
        const double bow = (dx == 0.0 ? 40.0 : 18.0) + 4.0 * static_cast<double>(k % 5);
        const double cx = mx - dy / length * bow, cy = my + dx / length * bow;
        // The curve leaves and meets each box at its edge, toward the control point.
        const auto edge = [&](double x, double y) {
            const double ex = cx - x, ey = cy - y;
            const double t = std::min(ex == 0.0 ? 1e9 : box_width / 2.0 / std::abs(ex),
                                      ey == 0.0 ? 1e9 : box_height / 2.0 / std::abs(ey));
            return std::pair<double, double>{x + t * ex, y + t * ey};
        };
        const auto [ax, ay] = edge(acx, acy);
        const auto [bx, by] = edge(bcx, bcy);
        svg << "<path d=\"M " << ax << ' ' << ay << " Q " << cx << ' ' << cy << ' ' << bx << ' ' << by
            << "\" fill=\"none\" stroke=\"#c0392b\" stroke-opacity=\"0.55\" stroke-width=\"1.4\" "
               "marker-end=\"url(#head)\"/>\n"
            << "<circle cx=\"" << (mx + cx) / 2.0 << "\" cy=\"" << (my + cy) / 2.0
            << "\" r=\"8\" fill=\"white\" stroke=\"#c0392b\"/>\n"
            << "<text x=\"" << (mx + cx) / 2.0 << "\" y=\"" << (my + cy) / 2.0 + 3.5
            << "\" font-size=\"9\" text-anchor=\"middle\">" << k + 2 << "</text>\n";
    }
    svg << "</svg>\n";
    return svg.str();
}

std::string read_all(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

}  // namespace

int main(int argc, char** argv)
{
    try {
        const std::vector<std::string> args(argv + 1, argv + argc);
        if (args.size() == 3 && (args[0] == "write" || args[0] == "check")) {
            const std::string drawn = svg_of(hops_of(args[1]));
            if (args[0] == "write") {
                std::ofstream(args[2], std::ios::binary) << drawn;
                std::cout << "wrote " << args[2] << '\n';
                return 0;
            }
            if (read_all(args[2]) != drawn) {
                std::cout << args[2] << " is not what " << args[1] << "'s list of hops draws now: redraw it "
                          << "(cmake --build build/test --target trip_map_refresh) and look at it\n";
                return 1;
            }
            std::cout << args[2] << " is the drawing of " << args[1] << "'s list\n";
            return 0;
        }
        std::cerr << "usage: trip_map write|check README.md MAP.svg\n";
        return 2;
    } catch (const std::exception& e) {
        std::cerr << "trip_map: " << e.what() << '\n';
        return 2;
    }
}
