// The time-series CSV's one column table: the header and the rows come from it, a column is found
// by its name, and the README's list of columns is the table (name, unit, meaning).
#include "scene/csv_columns.h"
#include "scene/csv_writer.h"
#include "scene/presets.h"
#include "scene/solution.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

using namespace chaplygin;

namespace {

std::vector<std::string> lines(const std::string& text) {
    std::vector<std::string> out;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);)
        out.push_back(line);
    return out;
}

std::vector<std::string> split(const std::string& line) {
    std::vector<std::string> out;
    std::istringstream in(line);
    for (std::string field; std::getline(in, field, ',');)
        out.push_back(field);
    return out;
}

std::string sourceFile(const std::string& name) {
    std::ifstream in(std::string(CHAPLYGIN_SOURCE_DIR) + "/" + name);
    EXPECT_TRUE(in) << "cannot read " << name;
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

// the table as README.md shows it
std::string markdownTable() {
    std::string out = "| column | unit | meaning |\n|---|---|---|\n";
    for (const CsvColumn& c : csvColumns())
        out += "| `" + std::string(c.name) + "` | " + std::string(c.unit) + " | " +
               std::string(c.meaning) + " |\n";
    return out;
}

} // namespace

TEST(CsvColumns, NamesAreUniqueIdentifiersAndEveryColumnHasAUnitAndAMeaning) {
    std::set<std::string_view> seen;
    for (const CsvColumn& c : csvColumns()) {
        EXPECT_TRUE(seen.insert(c.name).second) << c.name << " twice";
        ASSERT_FALSE(c.name.empty());
        EXPECT_TRUE(c.name[0] >= 'a' && c.name[0] <= 'z') << c.name;
        for (char ch : c.name)
            EXPECT_TRUE((ch >= 'a' && ch <= 'z') || (ch >= '0' && ch <= '9') || ch == '_')
                << c.name;
        EXPECT_FALSE(c.unit.empty()) << c.name;
        EXPECT_FALSE(c.meaning.empty()) << c.name;
        for (std::string_view text : {c.unit, c.meaning})
            EXPECT_EQ(text.find_first_of("|\n"), std::string_view::npos) << c.name << ": " << text;
        EXPECT_NE(c.value, nullptr) << c.name;
    }
}

TEST(CsvColumns, IndexFindsEveryColumnByItsName) {
    const auto columns = csvColumns();
    for (std::size_t i = 0; i < columns.size(); ++i)
        EXPECT_EQ(csvColumnIndex(columns[i].name), std::optional<std::size_t>(i))
            << columns[i].name;
    EXPECT_EQ(csvColumnIndex("no_such_column"), std::nullopt);
    EXPECT_EQ(csvColumnIndex(""), std::nullopt);
    EXPECT_EQ(csvColumnIndex("X"), std::nullopt);
}

TEST(CsvColumns, TheHeaderAndEveryRowAreTheTable) {
    Scene perturbed = presetScene("sinusoid");
    perturbed.perturbation = Perturbation{};
    perturbed.perturbation->dy = 0.1;
    for (const Scene& scene : {presetScene("sinusoid"), perturbed}) {
        const Solution solution = Solution::compute(scene);
        const std::vector<MotionSample> samples = solution.sample(7);
        const std::vector<std::string> csv = lines(formatCsv(samples));
        ASSERT_EQ(csv.size(), samples.size() + 1);
        const auto columns = csvColumnsWritten(scene.perturbation.has_value());
        const std::vector<std::string> header = split(csv[0]);
        ASSERT_EQ(header.size(), columns.size()) << csv[0];
        for (std::size_t i = 0; i < columns.size(); ++i)
            EXPECT_EQ(header[i], columns[i].name);
        // shortest round-trip digits: each field reads back as the accessor's value exactly
        for (std::size_t r = 0; r < samples.size(); ++r) {
            const std::vector<std::string> fields = split(csv[r + 1]);
            ASSERT_EQ(fields.size(), columns.size()) << csv[r + 1];
            for (std::size_t i = 0; i < columns.size(); ++i)
                EXPECT_EQ(std::strtod(fields[i].c_str(), nullptr), columns[i].value(samples[r]))
                    << columns[i].name << " at t = " << samples[r].t;
        }
    }
}

// docs/physics.md §9: the perturbed bodies' columns come after today's, and only when the scene
// has a perturbation; without one the header is the 27 columns it was, and the shared columns of a
// perturbed scene are the unperturbed scene's, byte for byte
TEST(CsvColumns, PerturbedColumnsOnlyWithAPerturbation) {
    const std::string today =
        "t,s,x,y,phi,psi,chi,lambda,energy,free_x,free_y,free_phi,free_sdot,free_phidot,"
        "free_energy,sdot,phidot,psidot,force_axial,force_lateral,control_couple,vak_x,vak_y,"
        "vak_phi,vak_sdot,vak_phidot,vak_lambda";
    const std::string added = ",pert_x,pert_y,pert_phi,pert_sdot,pert_phidot,fb_x,fb_y,fb_phi,"
                              "fb_sdot,fb_phidot,fb_lambda,fb_error";
    Scene scene = presetScene("circle");
    const std::vector<std::string> plain = lines(formatCsv(Solution::compute(scene).sample(9)));
    EXPECT_EQ(plain[0], today);
    EXPECT_EQ(csvColumnsWritten(false).size(), 27u);
    scene.perturbation = Perturbation{};
    scene.perturbation->dpsi = 0.1;
    const std::vector<std::string> withBodies =
        lines(formatCsv(Solution::compute(scene).sample(9)));
    EXPECT_EQ(withBodies[0], today + added);
    ASSERT_EQ(withBodies.size(), plain.size());
    for (std::size_t r = 1; r < plain.size(); ++r) {
        std::string prefix = withBodies[r];
        for (int i = 0; i < 12; ++i)
            prefix.resize(prefix.rfind(','));
        EXPECT_EQ(prefix, plain[r]) << "row " << r;
    }
}

// a sample of a few columns (the Python module's sample(t, columns)) computes only their bodies:
// each column read from Solution::at(t, csvColumnParts(column)) is the whole state's, bit for bit,
// and a part the column does not name is left out
TEST(CsvColumns, EachColumnNeedsOnlyItsPartsOfTheState) {
    Scene scene = presetScene("catenary");
    scene.perturbation = Perturbation{};
    scene.perturbation->dy = 0.05;
    const Solution solution = Solution::compute(scene);
    int skipped = 0;
    for (const CsvColumn& column : csvColumns()) {
        const MotionParts parts = csvColumnParts(column);
        const int named = parts.controlled + parts.free + parts.vakonomic + parts.perturbed;
        EXPECT_EQ(named, column.name == "t" ? 0 : 1) << column.name;
        EXPECT_EQ(parts.perturbed, column.perturbed) << column.name;
        for (double t : {0.0, 0.7, 2.9, solution.tEnd()}) {
            const double whole = column.value(solution.at(t));
            const double part = column.value(solution.at(t, parts));
            EXPECT_EQ(std::bit_cast<std::uint64_t>(part), std::bit_cast<std::uint64_t>(whole))
                << column.name << " at t = " << t;
            const MotionParts others{!parts.controlled, !parts.free, !parts.vakonomic,
                                     !parts.perturbed};
            skipped += column.value(solution.at(t, others)) != whole;
        }
    }
    EXPECT_GT(skipped, 100) << "the other parts were computed too";
}

// a zero that arithmetic made negative is written 0: a spreadsheet shows -0 as text
TEST(CsvColumns, NoNegativeZero) {
    MotionSample sample;
    sample.t = 0.5;
    sample.y = -0.0;
    sample.control.lambda = -0.0;
    sample.vak.lambda = -0.0;
    const std::vector<std::string> handMade = lines(formatCsv({sample}));
    ASSERT_EQ(handMade.size(), 2u);
    for (const std::string& field : split(handMade[1]))
        EXPECT_NE(field, "-0") << handMade[1];
    // the line preset's lambda, psidot and the forces are zeros of either sign
    int zeros = 0;
    for (const std::string& row :
         lines(formatCsv(Solution::compute(presetScene("line")).sample(51))))
        for (const std::string& field : split(row)) {
            EXPECT_NE(field, "-0") << row;
            zeros += field == "0";
        }
    EXPECT_GT(zeros, 51 * 5);
}

TEST(CsvColumns, AValueThatIsNotFiniteNamesItsColumn) {
    MotionSample sample;
    sample.t = 2.5;
    sample.vak.lambda = NAN;
    try {
        formatCsv({sample});
        FAIL() << "a NaN reached the CSV";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("column vak_lambda is not finite at t = 2.5"),
                  std::string::npos)
            << e.what();
    }
}

// README.md, Columns of the CSV: its table of the CSV's columns is the table, row for row
TEST(CsvColumns, TheReadmeListsEveryColumn) {
    const std::string readme = sourceFile("README.md");
    const std::vector<std::string> want = lines(markdownTable());
    const std::size_t at = readme.find(want[0] + "\n");
    ASSERT_NE(at, std::string::npos)
        << "README.md has no table headed '" << want[0] << "'; the table is:\n"
        << markdownTable();
    ASSERT_EQ(readme.find(want[0] + "\n", at + 1), std::string::npos) << "two tables";
    std::vector<std::string> got;
    for (const std::string& line : lines(readme.substr(at))) {
        if (line.empty() || line[0] != '|')
            break;
        got.push_back(line);
    }
    for (std::size_t i = 0; i < std::max(got.size(), want.size()); ++i)
        EXPECT_EQ(i < got.size() ? got[i] : "(no row)", i < want.size() ? want[i] : "(no column)")
            << "README.md's table, row " << i;
    if (got != want)
        ADD_FAILURE() << "README.md's CSV columns differ from csvColumns(); the table is:\n"
                      << markdownTable();
}

// docs/user-guide.md, Files: the first columns of File > Export CSV, in order
TEST(CsvColumns, TheUserGuideNamesTheFirstColumnsInOrder) {
    const std::string guide = sourceFile("docs/user-guide.md");
    const std::string open = "(`t,", ellipsis = ",…`)";
    const std::size_t from = guide.find(open);
    ASSERT_NE(from, std::string::npos) << "docs/user-guide.md lists no columns";
    const std::size_t to = guide.find(ellipsis, from);
    ASSERT_NE(to, std::string::npos);
    const std::vector<std::string> names = split(guide.substr(from + 2, to - from - 2));
    const auto columns = csvColumns();
    ASSERT_LE(names.size(), columns.size());
    for (std::size_t i = 0; i < names.size(); ++i)
        EXPECT_EQ(names[i], columns[i].name) << "column " << i + 1;
}
