#include "common/lesson_table.hpp"

#include "common/error.hpp"
#include "common/output.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <thread>

namespace rt {

LessonTable& LessonTable::row(std::vector<std::string> cells)
{
    cells.resize(columns.size());
    rows.push_back(std::move(cells));
    return *this;
}

bool LessonTable::timed() const
{
    return std::any_of(columns.begin(), columns.end(), [](const LessonColumn& c) { return c.timed; });
}

std::string fixed(double v, int decimals)
{
    std::ostringstream s;
    s << std::fixed << std::setprecision(decimals) << v;
    std::string text = s.str();
    // -0.004 at no decimals is "0", not "-0".
    if (text[0] == '-' && text.find_first_not_of("-0.") == std::string::npos)
        text.erase(0, 1);
    return text;
}

std::string significant(double v, int digits)
{
    if (v == 0.0 || !std::isfinite(v))
        return fixed(v, 0);
    // Trailing zeros are digits too: 0.900 s was measured to the millisecond, 0.9 s was not.
    const int magnitude = static_cast<int>(std::floor(std::log10(std::fabs(v))));
    return fixed(v, std::max(0, digits - 1 - magnitude));
}

std::string scientific(double v, int digits)
{
    if (v == 0.0)
        return "0";
    std::ostringstream s;
    s << std::scientific << std::setprecision(std::max(0, digits - 1)) << v;
    // 2.07e-02 reads as 2.07e-2 in a lesson.
    std::string text = s.str();
    const size_t e = text.find('e');
    if (e != std::string::npos) {
        size_t digit = e + 2;
        while (digit + 1 < text.size() && text[digit] == '0')
            text.erase(digit, 1);
        if (text[e + 1] == '+')
            text.erase(e + 1, 1);
    }
    return text;
}

std::string grouped(unsigned long long v)
{
    std::string digits = std::to_string(v);
    for (int k = static_cast<int>(digits.size()) - 3; k > 0; k -= 3)
        digits.insert(static_cast<size_t>(k), ",");
    return digits;
}

std::string spread(const Timing& t)
{
    if (t.runs < 2 || t.median <= 0.0)
        return "";
    return " ±" + fixed(100.0 * std::max(t.max - t.median, t.median - t.min) / t.median, 0) + "%";
}

LessonTable trade_lesson_table(const std::string& name, const TradeTable& table, const std::string& knob_header,
                               const std::string& error_header, bool with_rays_per_second, const std::string& caption)
{
    LessonTable t{name, {{knob_header}, {"seconds", true}, {"rays"}}, {}, caption};
    if (with_rays_per_second)
        t.columns.push_back({"rays/second", true});
    t.columns.push_back({error_header});
    for (const TradeRow& r : table.rows) {
        std::vector<std::string> cells{r.value, significant(r.seconds.median, 3) + spread(r.seconds), grouped(r.rays)};
        if (with_rays_per_second)
            cells.push_back(fixed(static_cast<double>(r.rays) / r.seconds.median / 1e6, 1) + " M");
        cells.push_back(scientific(r.error, 3));
        t.row(cells);
    }
    return t;
}

// The machine, as a reader would need it to compare: the processor's model where the system says
// it (Linux), and the number of hardware threads.
static std::string machine()
{
    std::string model;
    std::ifstream cpuinfo("/proc/cpuinfo");
    for (std::string line; model.empty() && std::getline(cpuinfo, line);)
        if (line.rfind("model name", 0) == 0 && line.find(':') != std::string::npos)
            model = line.substr(line.find(':') + 2);
    std::ostringstream s;
    s << (model.empty() ? "an unnamed processor" : model) << ", " << std::thread::hardware_concurrency()
      << " hardware threads";
    return s.str();
}

static std::string today()
{
    const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
    std::tm utc{};
#ifdef _WIN32
    gmtime_s(&utc, &now);
#else
    gmtime_r(&now, &utc);
#endif
    std::ostringstream s;
    s << std::put_time(&utc, "%Y-%m-%d");
    return s.str();
}

void write_lesson_table(std::ostream& out, const LessonTable& table)
{
    out << "<!-- table " << table.name;
    std::string timed;
    for (const LessonColumn& c : table.columns)
        if (c.timed)
            timed += (timed.empty() ? " timed: " : "; ") + c.header;
    out << timed << " -->\n|";
    for (const LessonColumn& c : table.columns)
        out << ' ' << c.header << " |";
    out << "\n|";
    for (size_t k = 0; k < table.columns.size(); ++k)
        out << (k == 0 ? "---|" : "---:|");
    out << '\n';
    for (const std::vector<std::string>& row : table.rows) {
        out << '|';
        for (const std::string& cell : row)
            out << ' ' << cell << " |";
        out << '\n';
    }
    std::string caption = table.caption;
    if (table.timed())
        caption += (caption.empty() ? "" : " ") + std::string("Timed on ") + machine() + ", " + today() + ".";
    if (!caption.empty())
        out << '\n' << caption << '\n';
    out << "<!-- end table -->\n";
}

void write_lesson_tables(const std::string& path, const std::vector<LessonTable>& tables, std::ostream& out)
{
    check_writable(path, "lesson tables");
    std::ofstream file(path);
    for (const LessonTable& t : tables) {
        write_lesson_table(file, t);
        file << '\n';
        write_lesson_table(out, t);
        out << '\n';
    }
    if (!file)
        throw InputError(path + ": cannot write the lesson tables");
}

std::string tables_beside(const std::string& csv)
{
    const std::string extension = ".csv";
    const bool has_extension =
        csv.size() >= extension.size() && csv.compare(csv.size() - extension.size(), extension.size(), extension) == 0;
    return (has_extension ? csv.substr(0, csv.size() - extension.size()) : csv) + ".tables.md";
}

}  // namespace rt
