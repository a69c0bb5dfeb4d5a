#include "common/nff.hpp"

#include "common/error.hpp"
#include "common/float_reach.hpp"
#include "common/number.hpp"
#include "common/polygon.hpp"
#include "common/words.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <sstream>
#include <string_view>
#include <vector>

namespace rt {

namespace {

// A message quotes at most this many characters of a token, so a line of garbage stays one
// readable line.
constexpr std::size_t quoted_token_limit = 32;

// Two points of an NFF file closer than this, relative to their size, are one point: 16 roundings
// of a float (2^-24 each), what reading decimals and forming a difference can move them.
constexpr double same_point_tolerance = 16.0 * 0x1p-24;

// The same test make_camera (camera.cpp) applies, so a view the reader accepts always makes a camera.
constexpr float up_parallel_tolerance = 1e-6f;

struct Token {
    std::string_view text;
    int line;
};

// The token as a message shows it: printable ASCII as is, other bytes as \xNN, long tokens cut.
std::string quote(std::string_view text)
{
    static const char hex[] = "0123456789abcdef";
    std::string out = "'";
    for (std::size_t i = 0; i < text.size() && i < quoted_token_limit; ++i) {
        const auto c = static_cast<unsigned char>(text[i]);
        if (c >= 0x20 && c < 0x7f) {
            out += static_cast<char>(c);
        } else {
            out += "\\x";
            out += hex[c >> 4];
            out += hex[c & 15];
        }
    }
    if (text.size() > quoted_token_limit)
        out += "...";
    return out + "'";
}

bool is_command(std::string_view word)
{
    for (const char* known : {"v", "b", "l", "f", "s", "p", "pp", "c"})
        if (word == known)
            return true;
    return false;
}

// Whitespace-separated tokens with their line numbers; `#` starts a comment to the end of the line
// (NFF: "As soon as a '#' character is detected, the rest of the line is considered a comment").
// A line ends at \n, \r\n or a lone \r, so files from any system count lines alike.
// Whether `after` (the text just after a '#' that ends a token) starts as Microsoft's spellings of
// NaN and infinity continue: QNAN, SNAN, IND or INF.
inline bool windows_non_number(std::string_view after)
{
    for (const std::string_view word : {"QNAN", "SNAN", "IND", "INF"})
        if (after.substr(0, word.size()) == word)
            return true;
    return false;
}

class Lexer {
public:
    explicit Lexer(std::string_view text) : text_(text)
    {
        // A UTF-8 byte order mark, as some Windows editors write, is not a token.
        if (text_.substr(0, 3) == "\xEF\xBB\xBF")
            pos_ = 3;
    }

    bool at_end()
    {
        skip_blanks();
        return pos_ >= text_.size();
    }

    // Call only when !at_end().
    Token peek()
    {
        skip_blanks();
        std::size_t end = pos_;
        while (end < text_.size() && !is_blank(text_[end]) && text_[end] != '#')
            ++end;
        // Microsoft's C library prints NaN and infinity as 1.#QNAN, -1.#IND, 1.#INF, 1.#SNAN: read
        // by the letter of NFF that is the number 1 and a comment, a wrong value and no word of it.
        // Such a token is kept whole, so that the number it stands for is refused by name.
        if (end > pos_ && end < text_.size() && windows_non_number(text_.substr(end + 1)))
            while (end < text_.size() && !is_blank(text_[end]))
                ++end;
        return {text_.substr(pos_, end - pos_), line_};
    }

    Token next()
    {
        const Token token = peek();
        pos_ += token.text.size();
        last_line_ = token.line;
        return token;
    }

    // Where the last token read stands (1 before any): a truncated command is reported there.
    int last_token_line() const { return last_line_; }

    // The number of the file's last line, for what is missing from the whole file. Call it once
    // every token is read: it counts the line breaks after the last one.
    int last_line()
    {
        skip_blanks();
        const bool ends_with_break = !text_.empty() && (text_.back() == '\n' || text_.back() == '\r');
        return ends_with_break && line_ > 1 ? line_ - 1 : line_;
    }

private:
    static bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v'; }

    void skip_blanks()
    {
        while (pos_ < text_.size()) {
            const char c = text_[pos_];
            if (c == '#') {
                while (pos_ < text_.size() && text_[pos_] != '\n' && text_[pos_] != '\r')
                    ++pos_;
            } else if (c == '\n' || (c == '\r' && (pos_ + 1 >= text_.size() || text_[pos_ + 1] != '\n'))) {
                ++line_;
                ++pos_;
            } else if (is_blank(c)) {
                ++pos_;
            } else {
                return;
            }
        }
    }

    std::string_view text_;
    std::size_t pos_ = 0;
    int line_ = 1;
    int last_line_ = 1;
};

class Parser {
public:
    Parser(std::string_view text, const std::string& name) : lex_(text), name_(name) {}

    NffScene parse()
    {
        scene_.name = name_;
        while (!lex_.at_end()) {
            const Token command = lex_.next();
            const std::string_view word = command.text;
            if (word == "v")
                read_view(command);
            else if (word == "b")
                scene_.background = read_colour("background");
            else if (word == "l")
                read_light(command);
            else if (word == "f")
                read_material(command);
            else if (word == "s")
                read_sphere(command);
            else if (word == "p" || word == "pp")
                read_polygon(command, word == "pp");
            else if (word == "c")
                read_cone(command);
            else if (double unused; parse_double(word, unused) != NumberStatus::not_a_number)
                fail(command.line, "unexpected number " + quote(word) +
                                       " where a command should start (too many numbers before it?)");
            else
                fail(command.line, "unknown command " + quote(word) +
                                       " (NFF has v, b, l, f, s, p, pp, c and # comments)");
        }
        if (view_line_ == 0)
            fail(lex_.last_line(), "no view ('v'): an NFF file must give one");
        if (scene_.spheres.empty() && scene_.triangles.empty() && scene_.cones.empty())
            fail(lex_.last_line(), "no objects (s, p, pp or c): nothing to render");
        if (scene_.lights.empty())
            fail(lex_.last_line(), "no lights ('l'): every object would be black");
        warn_if_coarse();
        const NffView& view = scene_.view;
        if (const std::string beyond = view_beyond_float(view.from, view.at, view.angle_degrees, view.width); !beyond.empty())
            scene_.warnings.push_back(name_ + ":" + std::to_string(view.line) + ": " + beyond);
        if (scene_.skipped_polygons > skipped_named)
            scene_.warnings.push_back(name_ + ": " + std::to_string(scene_.skipped_polygons) +
                                      " polygons and patches with no area skipped in all (the first " +
                                      std::to_string(skipped_named) + " named above)");
        return std::move(scene_);
    }

private:
    // How many skipped polygons the warnings name one by one before they only count them.
    static constexpr int skipped_named = 3;

    // The scene as float holds it (common/float_reach.hpp): a lattice too coarse for the scene, or
    // objects finer than a feeler's offset where they lie. Said once, as the reader's warnings are.
    void warn_if_coarse()
    {
        std::vector<Box> boxes;
        for (const NffSphere& s : scene_.spheres)
            boxes.push_back({s.center - vec3(s.radius), s.center + vec3(s.radius)});
        for (const NffTriangle& t : scene_.triangles)
            boxes.push_back({glm::min(t.p[0], glm::min(t.p[1], t.p[2])), glm::max(t.p[0], glm::max(t.p[1], t.p[2]))});
        for (const NffCone& c : scene_.cones) {
            const float r = std::max(c.base_radius, c.apex_radius);
            boxes.push_back({glm::min(c.base, c.apex) - vec3(r), glm::max(c.base, c.apex) + vec3(r)});
        }
        if (const std::string why = scene_beyond_float(boxes); !why.empty())
            scene_.warnings.push_back(name_ + ": " + why);
    }

    [[noreturn]] void fail(int line, const std::string& what) const
    {
        throw InputError(name_ + ":" + std::to_string(line) + ": " + what);
    }

    // The next token, which must exist: `entity: the file ends before FIELD` otherwise.
    Token expect(const std::string& entity, const std::string& field)
    {
        if (lex_.at_end())
            fail(lex_.last_token_line(), entity + ": the file ends before " + field);
        return lex_.next();
    }

    // `hint` follows the complaint when the token found is a command: the numbers ran short.
    float number(const std::string& entity, const std::string& field, const char* hint = " (too few numbers?)")
    {
        const Token token = expect(entity, field);
        double value = 0.0;
        const std::string where = entity + ": " + field;
        switch (parse_double(token.text, value)) {
        case NumberStatus::not_a_number:
            if (token.text.find('#') != std::string_view::npos)
                fail(token.line, where + " must be a number, got " + quote(token.text) +
                                     ", Microsoft's spelling of NaN or infinity: what wrote the file computed no number there");
            fail(token.line, where + " must be a number, got " + quote(token.text) +
                                 (is_command(token.text) ? hint : ""));
        case NumberStatus::out_of_range:
            fail(token.line, where + " is out of range, got " + quote(token.text));
        case NumberStatus::ok:
            break;
        }
        if (!std::isfinite(value))
            fail(token.line, where + " must be a finite number, got " + quote(token.text));
        if (std::abs(value) > nff_number_limit)
            fail(token.line, where + " is too large (the reader takes up to 1e12), got " + quote(token.text));
        last_number_ = token;
        return static_cast<float>(value);
    }

    float non_negative(const std::string& entity, const std::string& field)
    {
        const float value = number(entity, field);
        if (value < 0.0f)
            fail(last_number_.line, entity + ": " + field + " must not be negative, got " + quote(last_number_.text));
        return value;
    }

    // A whole number (a vertex count, a resolution); the caller checks its range.
    long long whole(const std::string& entity, const std::string& field)
    {
        const Token token = expect(entity, field);
        long long value = 0;
        const char* end = token.text.data() + token.text.size();
        const auto [ptr, ec] = std::from_chars(token.text.data(), end, value);
        if (ec == std::errc::result_out_of_range && ptr == end)
            fail(token.line, entity + ": " + field + " is out of range, got " + quote(token.text));
        if (ec != std::errc() || ptr != end)
            fail(token.line, entity + ": " + field + " must be a whole number, got " + quote(token.text));
        last_number_ = token;
        return value;
    }

    vec3 triple(const std::string& entity, const std::string& what, const char* hint = " (too few numbers?)")
    {
        vec3 v;
        v.x = number(entity, what + " x", hint);
        v.y = number(entity, what + " y", hint);
        v.z = number(entity, what + " z", hint);
        return v;
    }

    color read_colour(const std::string& entity)
    {
        color c;
        c.r = non_negative(entity, "red");
        c.g = non_negative(entity, "green");
        c.b = non_negative(entity, "blue");
        return c;
    }

    void read_view(const Token& command)
    {
        if (view_line_ != 0)
            fail(command.line, "a second view ('v'); the first is at line " + std::to_string(view_line_));
        view_line_ = command.line;
        NffView& view = scene_.view;
        view.line = command.line;
        static const std::array<std::string_view, 6> keywords = {"from", "at", "up", "angle", "hither", "resolution"};
        std::array<int, 6> seen_at{};  // the line of each keyword, 0 until seen
        for (std::size_t count = 0; count < keywords.size(); ++count) {
            std::vector<std::string> unseen;
            for (std::size_t k = 0; k < keywords.size(); ++k)
                if (seen_at[k] == 0)
                    unseen.push_back("'" + std::string(keywords[k]) + "'");
            const std::string missing = join_words(unseen, ", ", " or ");  // "'hither' or 'resolution'"
            if (lex_.at_end())
                fail(lex_.last_token_line(), "view: the file ends before " + missing);
            const Token key = lex_.next();
            std::size_t k = 0;
            while (k < keywords.size() && key.text != keywords[k])
                ++k;
            if (k == keywords.size())
                fail(key.line, "view: expected " + missing + ", got " + quote(key.text));
            if (seen_at[k] != 0)
                fail(key.line, "view: " + quote(key.text) + " is given twice");
            seen_at[k] = key.line;
            read_view_entry(k, view);
        }
        // What make_camera refuses, refused here with a line to point at.
        const vec3 back = view.from - view.at;
        if (back == vec3(0.0f))
            fail(seen_at[1], "view: from and at are the same point (no view direction)");
        const vec3 side = glm::cross(view.up, unit_or_zero(back));
        if (!(glm::length(side) > up_parallel_tolerance * glm::length(view.up)))
            fail(seen_at[2], "view: up is zero or parallel to the view direction");
    }

    void read_view_entry(std::size_t keyword, NffView& view)
    {
        switch (keyword) {
        case 0:
            view.from = triple("view", "from");
            break;
        case 1:
            view.at = triple("view", "at");
            break;
        case 2:
            view.up = triple("view", "up");
            break;
        case 3:
            view.angle_degrees = number("view", "angle");
            if (!(view.angle_degrees > 0.0f && view.angle_degrees < 180.0f))
                fail(last_number_.line, "view: angle must lie strictly between 0 and 180 degrees, got " +
                                            quote(last_number_.text));
            break;
        case 4:
            view.hither = non_negative("view", "hither");
            break;
        default:
            view.width = resolution("width");
            view.height = resolution("height");
            break;
        }
    }

    int resolution(const std::string& field)
    {
        const long long value = whole("view", "resolution " + field);
        if (value < 1 || value > nff_max_resolution)
            fail(last_number_.line, "view: resolution " + field + " must be between 1 and " +
                                        std::to_string(nff_max_resolution) + ", got " + quote(last_number_.text));
        return static_cast<int>(value);
    }

    void read_light(const Token& command)
    {
        NffLight light;
        light.line = command.line;
        light.position = triple("light", "position");
        // The colour is optional: it is there when a number follows.
        if (double unused; !lex_.at_end() && parse_double(lex_.peek().text, unused) != NumberStatus::not_a_number) {
            light.rgb = read_colour("light");
            light.rgb_given = true;
        }
        scene_.lights.push_back(light);
    }

    // A material's weight in [0, 1].
    float share(const char* field)
    {
        const float value = non_negative("material", field);
        if (value > 1.0f)
            fail(last_number_.line, std::string("material: ") + field + " must lie between 0 and 1, got " +
                                        quote(last_number_.text));
        return value;
    }

    void read_material(const Token& command)
    {
        NffMaterial m;
        m.line = command.line;
        m.rgb = read_colour("material");
        // Kd and Ks are shares of the light. A share above 1 makes light: a mirror of Ks = 1e11
        // between two others multiplies a path's colour by 1e11 at every bounce, to infinity and
        // NaN within five (the render fuzzer found it).
        m.kd = share("Kd");
        m.ks = share("Ks");
        m.shine = non_negative("material", "Shine");
        m.t = share("T");
        m.ior = non_negative("material", "index of refraction");
        if (m.t > 0.0f && !(m.ior > 0.0f))
            fail(last_number_.line, "material: a transmitting material (T > 0) needs an index of refraction above 0, got " +
                                        quote(last_number_.text));
        scene_.materials.push_back(m);
    }

    // The material of an object: the last `f` before it.
    int current_material(const Token& command, const char* entity)
    {
        if (scene_.materials.empty())
            fail(command.line, std::string(entity) + " comes before any material ('f'): NFF objects take the last 'f' before them");
        return static_cast<int>(scene_.materials.size()) - 1;
    }

    void read_sphere(const Token& command)
    {
        NffSphere s;
        s.material = current_material(command, "sphere");
        s.line = command.line;
        s.center = triple("sphere", "center");
        s.radius = number("sphere", "radius");
        if (!(s.radius > 0.0f))
            fail(last_number_.line, "sphere: radius must be above 0, got " + quote(last_number_.text));
        scene_.spheres.push_back(s);
    }

    void read_polygon(const Token& command, bool patch)
    {
        const std::string entity = patch ? "patch" : "polygon";
        const int material = current_material(command, entity.c_str());
        const long long count = whole(entity, "the vertex count");
        if (count < 3)
            fail(last_number_.line, entity + ": needs at least 3 vertices, got " + std::to_string(count));
        if (count > static_cast<long long>(polygon_max_vertices))
            fail(last_number_.line, entity + ": has " + std::to_string(count) + " vertices; the reader takes at most " +
                                        std::to_string(polygon_max_vertices));
        const std::string hint = " (fewer vertices than the " + std::to_string(count) + " announced?)";
        std::vector<point3> vertices;
        std::vector<vec3> normals;
        for (long long k = 1; k <= count; ++k) {
            const std::string index = std::to_string(k);
            vertices.push_back(triple(entity, "vertex " + index, hint.c_str()));
            if (!patch)
                continue;
            const dvec3 n(triple(entity, "normal " + index, hint.c_str()));
            const double length = glm::length(n);
            if (!(length > 0.0))
                fail(last_number_.line, entity + ": normal " + index + " is zero");
            normals.push_back(vec3(n / length));
        }
        PolygonTriangles cut;
        try {
            cut = triangulate_polygon(vertices);
        } catch (const DegeneratePolygon& e) {
            // The first few named, the rest counted (warn_of_skipped): a file of thousands of slivers
            // is one screen, not thousands of lines.
            if (scene_.skipped_polygons < skipped_named)
                scene_.warnings.push_back(name_ + ":" + std::to_string(command.line) + ": " + entity + ": " + e.what() +
                                          ": skipped");
            ++scene_.skipped_polygons;
            return;
        } catch (const InputError& e) {
            fail(command.line, entity + ": " + e.what());
        }
        const vec3 face(cut.normal);
        for (const TriangleIndices& t : cut.triangles) {
            NffTriangle tri;
            for (int k = 0; k < 3; ++k) {
                tri.p[k] = vertices[t[k]];
                tri.n[k] = patch ? normals[t[k]] : face;
            }
            tri.smooth = patch;
            tri.material = material;
            tri.line = command.line;
            scene_.triangles.push_back(tri);
        }
    }

    void read_cone(const Token& command)
    {
        NffCone c;
        c.material = current_material(command, "cone");
        c.line = command.line;
        // NFF gives both radii negative for a cone seen only from inside; the kit's cones are seen
        // from outside only, so a negative radius is refused rather than silently flipped.
        const char* inside_only = " (NFF's inside-only cones are not supported)";
        c.base = triple("cone", "base");
        c.base_radius = number("cone", "base radius");
        if (c.base_radius < 0.0f)
            fail(last_number_.line, "cone: base radius must not be negative, got " + quote(last_number_.text) + inside_only);
        c.apex = triple("cone", "apex");
        c.apex_radius = number("cone", "apex radius");
        if (c.apex_radius < 0.0f)
            fail(last_number_.line, "cone: apex radius must not be negative, got " + quote(last_number_.text) + inside_only);
        const double axis = glm::length(dvec3(c.apex) - dvec3(c.base));
        const double size = std::max({glm::length(dvec3(c.base)), glm::length(dvec3(c.apex)),
                                      double(c.base_radius), double(c.apex_radius)});
        if (!(axis > same_point_tolerance * size))
            fail(command.line, "cone: base and apex are the same point (NFF: they cannot be coincident)");
        if (c.base_radius == 0.0f && c.apex_radius == 0.0f)
            fail(command.line, "cone: both radii are 0 (a line, no surface)");
        scene_.cones.push_back(c);
    }

    Lexer lex_;
    std::string name_;
    NffScene scene_;
    int view_line_ = 0;
    Token last_number_{};
};

}  // namespace

NffScene parse_nff(std::istream& in, const std::string& name)
{
    const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    if (in.bad())
        throw InputError(name + ":1: cannot read the file");
    return Parser(text, name).parse();
}

NffScene read_nff(const std::string& path)
{
    std::error_code error;
    if (!std::filesystem::exists(path, error))
        throw InputError(path + ":1: no such file");
    if (std::filesystem::is_directory(path, error))
        throw InputError(path + ":1: is a folder, not an NFF file");
    std::ifstream in(path, std::ios::binary);
    if (!in)
        throw InputError(path + ":1: cannot open the file");
    return parse_nff(in, path);
}

}  // namespace rt
