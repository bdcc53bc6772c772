// A sleigh driven through a cusp (docs/physics.md §3) against an independent reference:
// tests/core/scene/cusp_reference.py derives every controlled column at 30 digits in the curve
// parameter u (signed speed, dphi/du; never the curvature, which is infinite at the cusp) and a
// Newton-Euler balance, and prints the tables below. A second scene turns right and is rotated, so
// Psi leaves (0, pi) above pi; the astroid has two cusps and a duration by independent quadrature.
#include "common/input_error.h"
#include "control/piece_control.h"
#include "gsl_quadrature.h"
#include "scene/csv_columns.h"
#include "scene/solution.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>
#include <string_view>
#include <vector>

using namespace chaplygin;

namespace {

// the reference's columns, in the order cusp_reference.py prints a row
constexpr auto kReferenceColumns = std::to_array<std::string_view>(
    {"t", "s", "x", "y", "phi", "psi", "chi", "lambda", "energy", "sdot", "phidot", "psidot",
     "force_axial", "force_lateral", "control_couple"});
using Row = std::array<double, kReferenceColumns.size()>;

// the position of a column in a reference row; a name it lacks does not compile
consteval std::size_t column(std::string_view name) {
    for (std::size_t k = 0; k < kReferenceColumns.size(); ++k)
        if (kReferenceColumns[k] == name)
            return k;
    throw "not a column of the reference";
}

struct Reference {
    const char* x;
    const char* y;
    double u0, u1, vT;
    std::array<double, 3> summary; // cusp time, duration, path length
    std::vector<Row> rows;         // kReferenceColumns
};

const std::vector<Reference>& references() {
    static const std::vector<Reference> refs = {
        {"u^2",
         "u^3",
         -1,
         1,
         1.0,
         {1.9478305436347380285, 3.895661087269476057, 2.8794197467431008008},
         {
             {0.0, 0.0, 1.0, -1.0, 2.1587989303424641705, 1.4434809720701432978,
              0.36408150689891121252, -0.1700946754254385854, 0.5, 0.99190634173531852608,
              0.12697168670714546793, -0.10660883207186585144, -0.021597207838672383323,
              0.17881700957418731067, 0.16871798724990317159},
             {0.5999999999999999778, 0.5908238457100632455, 0.65014122342093413081,
              -0.52421754985860315824, 2.2616714547877376815, 1.3346247211906575853,
              0.20378899379678874456, -0.41851079029314586847, 0.5, 0.97224087378277748693,
              0.23398222869718404294, -0.301519675944553847, -0.097924087446610088223,
              0.37406196307970836051, 0.40689329644212888975},
             {1.8978305436347380257, 1.4385969492440845723, 0.0011122285754422902239,
              -0.000037092924299415609292, 3.0916091839552006712, 0.044604206552674211552,
              -1.501200385424926124, -1.3979753980388453598, 0.5, 0.044589417750411930464,
              0.99900539729506929699, -0.89847269939131071134, -1.396584967926529348,
              0.064576256260155801807, 0.062334909027952475131},
             {1.9478305436347380285, 1.4397098733715504004, 0.0, 0.0, 3.1415926535897932385, 0.0,
              -1.5707963267948966192, -1.3888888888888891362, 0.5, 0.0, 1.0,
              -0.88888888888888913621, -1.3888888888888891099, 0.0, 0.0},
             {1.9478315436347380285, 1.4397098733719948448, 4.4444444444462364519e-13,
              2.9629629629647549704e-19, 3.1415936535897932383, -8.8888888889016731231e-7,
              -1.5707977156837855093, -1.388888888892526749, 0.5, -8.8888888889005025699e-7,
              0.99999999999960493827, -0.88888888889272427984, -1.3888888888919780521,
              -1.2839506172869816012e-6, -1.2345679012394145659e-6},
             {2.2478305436347380174, 1.4819571443768183474, 0.041302089943112039868,
              0.0083937888897915214628, 3.4374872956131156863, -0.30024859731740963445,
              -2.0189922451239674776, -1.6920539176793789479, 0.5, -0.29575769161564665566,
              0.95526299407554988355, -1.2144224206416040061, -1.6163564915396675422,
              -0.4621137639012591013, -0.50043796078206453155},
             {3.895661087269476057, 2.8794197467431008008, 1.0, 1.0, 4.1243863768371223064,
              -1.4434809720701432978, -3.505674160488704451, -0.1700946754254385854, 0.5,
              -0.99190634173531852608, 0.12697168670714546793, -0.10660883207186585144,
              -0.021597207838672383323, -0.17881700957418731067, -0.16871798724990317159},
         }},
        {"cos(0.3)*u^2+sin(0.3)*u^3",
         "sin(0.3)*u^2-cos(0.3)*u^3",
         -1,
         1.2,
         0.8,
         {2.4347881795434225356, 5.9380910685050658594, 3.7302859799069505566},
         {
             {0.0, 0.0, 0.65981628246426644454, 1.2508566957869455947, -1.8587989303424641705,
              1.6981116815196499407, 2.6275111466908820259, 0.13607574034035086832, 0.32,
              0.79352507338825482086, -0.10157734936571637434, 0.085287065657492681149,
              -0.013822213016750325327, -0.11444288612747987883, -0.10797951183993802982},
             {1.1000000000000000888, 0.85909393528839585117, 0.35490319662499553319,
              0.448911339674250292, -2.0413095543321833732, 1.9242705373138574774,
              2.9449253144799491639, 0.5963698385871021853, 0.32, 0.75054059752042573393,
              -0.27692744803230016522, 0.45790611457095210268, -0.16515117748336097821,
              -0.37968385673513866955, -0.44759977499632352159},
             {2.4346881795434225356, 1.4397098705271059441, 2.7173567445721508488e-9,
              8.4073574031278996418e-10, -2.8415126535898606623, 3.141521542478027554,
              4.5622778692729578851, 1.1111111297369546914, 0.32, 0.000056888889364601738587,
              -0.79999999797728391423, 0.71111113074831273424, -0.88888890154210139789,
              -0.000065738272598150121588, -0.0000632098781313832643},
             {2.4347881795434225356, 1.4397098733715504004, 0.0, 0.0, -2.8415926535897932385,
              3.1415926535897932385, 4.5623889803846898577, 1.111111111111111309, 0.32, 0.0, -0.8,
              0.71111111111111130898, -0.88888888888888903033, 0.0, 0.0},
             {2.454788179543422536, 1.4398236701760491127, 0.00010906598960487720511,
              0.000032467498736134231253, -2.857592113965958185, 3.155820112251451824,
              4.5846161692344309165, 1.1118560787562537598, 0.32, -0.011381582942488726859,
              -0.79991903313380614275, 0.71189656218935068845, -0.88939483950264752345,
              0.013155599707403142185, 0.012654682180474580298},
             {3.3347881795434225578, 1.7145031028514985431, 0.26859726029925090796,
              -0.042993819092851632293, -3.4791708278146360802, 4.0450579540630102962,
              5.7846433679703283363, 1.2856543091220930279, 0.32, -0.62838101393850662065,
              -0.49511342268374662611, 1.0380975977802197149, -0.63654470537754709105,
              0.6372802850907083508, 0.80788075834055103854},
             {5.9380910685050658594, 3.7302859799069505566, 1.8863434614516672956,
              -1.225272355616718062, -3.9052904759923528837, 4.6409243735691896783,
              6.5935696115653661201, 0.060114141474133633141, 0.32, -0.797957993287414126,
              -0.057123033434186184131, 0.031552624757040541075, -0.0034339021132943338713,
              0.058170615696672498228, 0.047968559698895388747},
         }},
    };
    return refs;
}

Scene sleighOn(const char* x, const char* y, double u0, double u1, double vT) {
    Scene s;
    s.system.kind = SystemKind::Sleigh;
    s.system.params = {{"a", 0.5}, {"b", 1.0}, {"m", 1.0}};
    s.path.kind = PathKind::Parametric;
    s.path.xOfU = x;
    s.path.yOfU = y;
    s.path.from = u0;
    s.path.to = u1;
    s.mode = SpeedMode::Energy;
    s.speed = vT;
    return s;
}

// a sample's values of the reference's columns, read through the CSV's column table
Row columnsOf(const MotionSample& m) {
    Row row{};
    for (std::size_t k = 0; k < kReferenceColumns.size(); ++k)
        row[k] = csvColumns()[csvColumnIndex(kReferenceColumns[k]).value()].value(m);
    return row;
}

} // namespace

TEST(Cusp, EveryControlledColumnAgreesWithTheReference) {
    for (const Reference& ref : references()) {
        Solution s = Solution::compute(sleighOn(ref.x, ref.y, ref.u0, ref.u1, ref.vT));
        EXPECT_NEAR(s.duration(), ref.summary[1], 1e-13) << ref.y;
        EXPECT_NEAR(s.path()->length(), ref.summary[2], 1e-13) << ref.y;
        for (const Row& want : ref.rows) {
            Row got = columnsOf(s.at(std::min(want[column("t")], s.duration())));
            for (std::size_t q = 0; q < kReferenceColumns.size(); ++q) {
                if (q == column("t"))
                    continue; // the time asked for
                EXPECT_NEAR(got[q], want[q], 1e-11 * std::max(1.0, std::fabs(want[q])))
                    << ref.y << " at t = " << want[column("t")] << ": " << kReferenceColumns[q];
            }
        }
    }
}

TEST(Cusp, TheSleighBacksUpAndPsiLeavesItsRangeContinuously) {
    for (const Reference& ref : references()) {
        Solution s = Solution::compute(sleighOn(ref.x, ref.y, ref.u0, ref.u1, ref.vT));
        const double tCusp = ref.summary[0];
        double previous = NAN, psiMin = INFINITY, psiMax = -INFINITY, largestStep = 0;
        const int n = 4000;
        for (int i = 0; i <= n; ++i) {
            const double t = s.duration() * i / n;
            MotionSample m = s.at(t);
            if (t < tCusp - 1e-9) {
                EXPECT_GT(m.control.sdot, 0) << t;
            } else if (t > tCusp + 1e-9) {
                EXPECT_LT(m.control.sdot, 0) << t;
            }
            EXPECT_NEAR(m.control.energy, 0.5 * ref.vT * ref.vT, 1e-14) << t;
            if (std::isfinite(previous))
                largestStep = std::max(largestStep, std::fabs(m.control.psi - previous));
            previous = m.control.psi;
            psiMin = std::min(psiMin, m.control.psi);
            psiMax = std::max(psiMax, m.control.psi);
        }
        EXPECT_LT(largestStep, 0.01) << ref.y; // |Psidot| dt <= 1.3 * 1e-3: no jump
        EXPECT_TRUE(psiMin < 0 || psiMax > std::numbers::pi)
            << ref.y << " " << psiMin << " " << psiMax;
        // at the cusp itself: sdot = 0 and |phidot| = v_T/b
        MotionSample at = s.at(tCusp);
        EXPECT_NEAR(at.control.sdot, 0, 1e-12);
        EXPECT_NEAR(std::fabs(at.control.phidot), ref.vT, 1e-12);
    }
}

TEST(Cusp, TableNodesIncludeTheCuspWithItsLimits) {
    const Reference& ref = references()[0];
    Solution s = Solution::compute(sleighOn(ref.x, ref.y, ref.u0, ref.u1, ref.vT));
    bool seen = false;
    for (const MotionSample& m : s.controlledAtNodes()) {
        EXPECT_TRUE(std::isfinite(m.control.psi) && std::isfinite(m.control.lambda) &&
                    std::isfinite(m.control.controlCouple))
            << m.t;
        if (std::fabs(m.t - ref.summary[0]) < 1e-12) {
            seen = true;
            const Row& want = ref.rows[3]; // the row at the cusp
            Row got = columnsOf(m);
            for (std::size_t q = 0; q < kReferenceColumns.size(); ++q) {
                if (q == column("t"))
                    continue; // the time asked for
                EXPECT_NEAR(got[q], want[q], 1e-11 * std::max(1.0, std::fabs(want[q])))
                    << kReferenceColumns[q];
            }
        }
    }
    EXPECT_TRUE(seen);
}

// u = 1e-200 from the cusp: |r'|^3 underflows and the exact curvature is not a number; the state
// is the cusp's limit, as the reference's row at the cusp
TEST(Cusp, StateBesideTheCuspWhereTheCurvatureUnderflows) {
    const Reference& ref = references()[0];
    Solution s = Solution::compute(sleighOn(ref.x, ref.y, ref.u0, ref.u1, ref.vT));
    for (const PathPiece& piece : s.path()->pieces())
        for (double u : {-1e-200, 1e-200}) {
            if (u < piece.table->nodes().front().u || u > piece.table->nodes().back().u)
                continue;
            PathNode n = piece.table->at(u);
            ControlState c = controlOnPiece(controlParamsOf(s.scene()), piece, n);
            const Row& want = ref.rows[3];
            EXPECT_NEAR(c.psi, want[column("psi")], 1e-12) << u;
            EXPECT_NEAR(c.lambda, want[column("lambda")], 1e-12) << u;
            EXPECT_NEAR(c.sdot, want[column("sdot")], 1e-12) << u;
            EXPECT_NEAR(c.phidot, want[column("phidot")], 1e-12) << u;
            EXPECT_NEAR(c.controlCouple, want[column("control_couple")], 1e-12) << u;
        }
}

TEST(Cusp, ConstantSpeedRefusesTheCuspNamingIt) {
    Scene scene = sleighOn("u^2", "u^3", -1, 1, 1.0);
    scene.mode = SpeedMode::Speed;
    try {
        Solution::compute(scene);
        ADD_FAILURE() << "accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("path at u = 0: constant-speed mode cannot pass"),
                  std::string::npos)
            << e.what();
    }
}

// The astroid x = cos^3 u, y = sin^3 u has cusps at u = pi/2 and pi: forward, backing, forward.
// Its heading turns at dphi/du = -1 and its speed is |3 sin u cos u|, so the time to pass is
// (1/v_T) \int sqrt((9/4) sin^2 2u + b^2) du, here by GSL's adaptive quadrature.
TEST(Cusp, TwoCuspsOnTheAstroid) {
    const double u0 = 0.3, u1 = 3.6, b = 1.0, vT = 1.0;
    Solution s = Solution::compute(sleighOn("cos(u)^3", "sin(u)^3", u0, u1, vT));
    ASSERT_EQ(s.path()->pieces().size(), 3u);
    auto rate = [](double u) { return std::sqrt(2.25 * std::pow(std::sin(2 * u), 2) + 1.0); };
    auto timeTo = [&](double u) {
        return test::gslIntegral(rate, u0, u, 0, 1e-13, test::GslRule::GaussKronrod61, 200) / vT;
    };
    EXPECT_NEAR(s.duration(), timeTo(u1), 1e-12);
    // the time of each cusp, and the sign of sdot on each stretch
    const double t1 = timeTo(std::numbers::pi / 2), t2 = timeTo(std::numbers::pi);
    for (double t : {0.5 * t1, 0.5 * (t1 + t2), 0.5 * (t2 + s.duration())}) {
        MotionSample m = s.at(t);
        const double sign = t < t1 ? 1 : (t < t2 ? -1 : 1);
        EXPECT_GT(sign * m.control.sdot, 0) << t;
        EXPECT_NEAR(m.control.energy, 0.5 * vT * vT, 1e-14);
        // the heading is pi - u (mod pi), so dphi/dt = -v_T/sqrt((9/4) sin^2 2phi + b^2)
        EXPECT_NEAR(m.control.phidot, -vT / std::hypot(1.5 * std::sin(2 * m.phi), b), 1e-12) << t;
    }
    for (double t : {t1, t2}) {
        MotionSample m = s.at(t);
        EXPECT_NEAR(m.control.sdot, 0, 1e-12) << t;
        EXPECT_NEAR(m.control.phidot, -vT / b, 1e-12) << t;
        // P at the cusp points (0, 1) and (-1, 0)
        EXPECT_NEAR(m.x, t == t1 ? 0.0 : -1.0, 1e-12);
        EXPECT_NEAR(m.y, t == t1 ? 1.0 : 0.0, 1e-12);
    }
}
