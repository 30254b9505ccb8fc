/// @file ValidateCommandSlowTest.cpp
/// `modeflow validate --quick`: every study runs and its numbers meet the seed's claims, checked
/// here against expectations of our own (not the report's verdicts): second order for cut cells,
/// energy exact under the midpoint rule, cross helicity conserved, grid-evaluated coefficients
/// drifting, the error against the full run falling with more modes, LANS-α's spectrum steeper
/// than Navier–Stokes'. Speed is reported, never asserted. Label `slow` (its time:
/// tools/validate/README.md).

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/support/CliFixture.h"

namespace modeflow {
namespace {

using testing::Cli;
using testing::RunResult;
namespace fs = std::filesystem;
using nlohmann::json;

/// The data of study `key` in results.json.
const json& study(const json& results, const std::string& key) {
    return results.at("studies").at(key).at("data");
}

/// A progress line per study, every headline met, every figure inline in the report.
void checkProgressAndReport(const json& results, const std::string& err, const std::string& html) {
    for (const char* key : {"convergence", "integrators", "mhd", "coefficients", "resolution",
                            "speed", "reduced_vs_full", "lans_alpha", "wake"}) {
        EXPECT_NE(err.find(std::string("] ") + key + ": "), std::string::npos) << key << "\n"
                                                                               << err;
        EXPECT_NE(err.find(std::string("validate: ") + key + " done in "), std::string::npos)
            << key;
        ASSERT_TRUE(results["studies"].contains(key)) << key;
        EXPECT_TRUE(results["studies"][key]["headline"]["met"].get<bool>()) << key;
        EXPECT_NE(html.find(std::string("id='") + key + "'"), std::string::npos) << key;
    }
    EXPECT_TRUE(results["quick"].get<bool>());
    // Every figure inline: no reference to a file beside the report.
    EXPECT_EQ(html.find("src='figures/"), std::string::npos);
    EXPECT_GE(html.size(), 100000u);
}

/// Cut cells converge at second order; the staircase is further off at every resolution.
void checkConvergence(const json& results) {
    for (const json& s : study(results, "convergence")["series"]) {
        const double order = s["order"];
        const std::string what = s["domain"].get<std::string>() + " " +
                                 s["field"].get<std::string>() + " " +
                                 s["boundary"].get<std::string>();
        if (s["boundary"] == "cut-cell") {
            EXPECT_GE(order, 1.8) << what;
            EXPECT_LE(order, 2.3) << what;
        }
    }
    // At every resolution the staircase's velocity eigenvalues are further off than cut cells'.
    for (const char* domain : {"disk", "ball"}) {
        json cut, stairs;
        for (const json& s : study(results, "convergence")["series"])
            if (s["domain"] == domain && s["field"] == "velocity")
                (s["boundary"] == "cut-cell" ? cut : stairs) = s;
        for (std::size_t i = 0; i < cut["max_relative_error"].size(); ++i)
            EXPECT_GT(stairs["max_relative_error"][i].get<double>(),
                      cut["max_relative_error"][i].get<double>())
                << domain << " at " << cut["resolution"][i];
    }
}

/// Midpoint keeps energy exactly, explicit Euler gains it, RK4 and trapezoidal converge at their
/// orders, the implicit rules run back to their start.
void checkIntegrators(const json& results) {
    std::map<std::string, std::vector<double>> drift;
    for (const json& s : study(results, "integrators")["series"])
        drift[s["integrator"]].push_back(s["max_relative_drift"]);
    for (const double d : drift["midpoint"]) EXPECT_LT(d, 1e-12);
    for (const double d : drift["linearized"]) EXPECT_LT(d, 1e-12);
    EXPECT_EQ(drift["linearized"].size(), 3u);
    for (const double d : drift["explicit"]) EXPECT_GT(d, 1e-2) << "explicit Euler gains energy";
    // Steps halve: RK4's drift falls about 2⁴-fold, the trapezoidal rule's 2²-fold.
    EXPECT_GT(drift["rk4"][0] / drift["rk4"][1], 8.0);
    EXPECT_GT(drift["trapezoidal"][0] / drift["trapezoidal"][1], 3.0);
    for (const json& r : study(results, "integrators")["reversibility"]) {
        const double e = r["return_error"];
        if (r["integrator"] == "midpoint" || r["integrator"] == "trapezoidal") {
            EXPECT_LT(e, 1e-12) << r;
        } else if (r["integrator"] == "explicit") {
            EXPECT_GT(e, 1e-3) << r;
        }
    }
}

/// MHD conserves energy and cross helicity; the field brakes the rotor.
void checkMhd(const json& results) {
    const json& mhd = study(results, "mhd");
    EXPECT_LT(mhd["random"]["max_relative_cross_helicity_drift"].get<double>(), 1e-10);
    EXPECT_LT(mhd["random"]["max_relative_energy_drift"].get<double>(), 1e-10);
    const json& field = mhd["runs"][0];
    const json& plain = mhd["runs"][1];
    EXPECT_LT(field["max_relative_energy_drift"].get<double>(), 1e-10);
    // The wound-up field takes kinetic energy from the rotor; without a field none is lost.
    const double k0 = field["kinetic_energy"][0], kEnd = field["kinetic_energy"].back();
    EXPECT_LT(kEnd, 0.95 * k0);
    EXPECT_NEAR(plain["kinetic_energy"].back().get<double>(),
                plain["kinetic_energy"][0].get<double>(),
                1e-10 * plain["kinetic_energy"][0].get<double>());
    EXPECT_EQ(field["pictures"].size(), 4u);
}

/// Grid-evaluated coefficients are not antisymmetric and drift in energy; ours keep it.
void checkCoefficients(const json& results) {
    for (const json& run : study(results, "coefficients")["runs"]) {
        const double drift = run["max_relative_energy_drift"];
        if (run["coefficients"] == "ours") {
            EXPECT_LT(drift, 1e-12) << run["modes"];
        } else {
            EXPECT_GT(drift, 1e-5) << run["modes"];
        }
        for (const double e : run["relative_l2"]) EXPECT_LT(e, 1.0) << run["modes"];
    }
    for (const json& a : study(results, "coefficients")["grid_antisymmetry"])
        EXPECT_GT(a["antisymmetry_error"].get<double>(), 1e-3);
}

/// The smoke rises alike on every grid.
void checkResolution(const json& results) {
    const json& runs = study(results, "resolution")["runs"];
    for (const json& run : runs) {
        EXPECT_GT(run["centroid_y"].back().get<double>() - run["centroid_y"][0].get<double>(), 0.1)
            << run["resolution"];
        EXPECT_LT(run["max_centroid_distance_to_finest"].get<double>(), 0.05) << run["resolution"];
        EXPECT_LT(run["max_energy_difference_to_finest"].get<double>(), 0.1) << run["resolution"];
    }
}

/// Speed is measured for every row (never asserted).
void checkSpeed(const json& results) {
    for (const json& row : study(results, "speed")["rows"]) {
        EXPECT_GT(row["midpoint_seconds"].get<double>(), 0.0);
        EXPECT_TRUE(std::isfinite(row["speedup"].get<double>()));
    }
}

/// The error against the full run falls, and the rise grows towards the full run's, with more
/// modes.
void checkReducedVsFull(const json& results) {
    const json& plume = study(results, "reduced_vs_full")["plume"];
    double previouerror = 2.0, previousRise = 0.0;
    for (const json& run : plume["runs"]) {
        if (run["modes"] == plume["full_modes"]) continue;
        const double error = run["relative_l2"].back(), rise = run["rise_fraction_of_full"];
        EXPECT_LT(error, previouerror) << run["modes"] << " modes";
        EXPECT_GT(rise, previousRise) << run["modes"] << " modes";
        previouerror = error, previousRise = rise;
    }
    EXPECT_NEAR(previousRise, 1.0, 0.05) << "the most modes rise as the full run";
    // The 3D ball: the first step's response grows towards the full grid's with more modes.
    double previousResponse = 0.0;
    for (const json& run : study(results, "reduced_vs_full")["plume_3d"]["runs"]) {
        const double response = run["response_rise_fraction"];
        EXPECT_GT(response, previousResponse) << run["modes"] << " modes";
        EXPECT_LT(response, 1.0) << run["modes"] << " modes";
        previousResponse = response;
    }
    // The periodic band-limited flow (seed Fig. 6.12): every run starts on the full run's field
    // (the same band-limited flow read through the staggered faces), and the final error falls
    // as the mode count grows, while the full spectrum keeps its energy.
    const json& periodic = study(results, "reduced_vs_full")["periodic"];
    double previousFinal = 2.0;
    for (const json& run : periodic["runs"]) {
        EXPECT_LT(run["relative_l2"][0].get<double>(), 0.02) << run["modes"] << " modes at t = 0";
        const double final = run["relative_l2"].back();
        EXPECT_LT(final, previousFinal) << run["modes"] << " modes";
        previousFinal = final;
    }
    const json& energy = periodic["full_energy"];
    EXPECT_NEAR(energy.back().get<double>() / energy[0].get<double>(), 1.0, 1e-3)
        << "the full spectrum's energy";
    // The seed's fluid markers: the most modes carry them nearer to where the full run does.
    const auto markerDistance = [&](const json& markers) {
        double sum = 0.0;
        int count = 0;
        for (int disk = 0; disk < 2; ++disk) {
            const json& full = periodic["full_markers"][disk];
            EXPECT_EQ(markers[disk].size(), periodic["markers_start"][disk].size());
            for (std::size_t i = 0; i < full.size(); ++i, ++count)
                for (int axis = 0; axis < 2; ++axis) {
                    const double period = 2.0 * std::numbers::pi,
                                 d = markers[disk][i][axis].get<double>() -
                                     full[i][axis].get<double>();
                    sum += std::abs(d - period * std::round(d / period));
                }
        }
        return sum / count;
    };
    const double fewest = markerDistance(periodic["runs"].front()["markers"]),
                 most = markerDistance(periodic["runs"].back()["markers"]);
    EXPECT_LT(most, fewest) << "mean marker distance from the full run's";
    // The outside check (Blender's Mantaflow) is the full report's alone, and says so.
    EXPECT_NE(study(results, "reduced_vs_full")["plume_3d"]["mantaflow"]["not_run"]
                  .get<std::string>()
                  .find("--quick"),
              std::string::npos);
}

/// Held low modes drive both models, the nonlinear term carries their energy up the shells (a
/// positive flux above the forcing), LANS-α's spectrum falls off more steeply beyond κ = 1/α, and
/// the largest basis's inertial range and slope are reported.
void checkLansAlpha(const json& results) {
    const json& lans = study(results, "lans_alpha");
    EXPECT_LT(lans["transfer_sum_relative_max"].get<double>(), 1e-12);
    const json& range = lans["inertial_range"];
    ASSERT_EQ(range.size(), 2u);
    EXPECT_GE(range[0].get<int>(), 3);
    EXPECT_GT(range[1].get<int>(), range[0].get<int>());
    EXPECT_LE(range[1].get<int>(), int(lans["kappa"].size()));
    EXPECT_LT(lans["inertial_slope"].get<double>(), 0.0);
    for (const json& run : lans["runs"]) {
        const int modes = run["modes"];
        const double ns = run["navier_stokes"]["beyond_alpha_slope"],
                     alpha = run["lans_alpha"]["beyond_alpha_slope"];
        EXPECT_LT(alpha, ns - 0.5) << modes << " modes: LANS-α " << alpha << ", NS " << ns;
        for (const char* model : {"navier_stokes", "lans_alpha"}) {
            const json& m = run[model];
            const json& energy = m["total_energy"];
            EXPECT_GT(energy.back().get<double>(), 1.2 * energy[0].get<double>())
                << modes << " modes, " << model << ": no energy fed in";
            EXPECT_GT(m["injection_mean"].get<double>(), 0.0) << modes << " modes, " << model;
            // Shell 2 is the first the forcing does not hold whole: energy crosses it upwards.
            EXPECT_GT(m["flux"][1].get<double>(), 0.0) << modes << " modes, " << model;
        }
    }
}

/// The wake sheds (the probe swings both ways, several periods) at Roshko's Strouhal number
/// within 20% at Re 100 and 150.
void checkWake(const json& results) {
    const json& wake = study(results, "wake");
    for (const char* key : {"re_100", "re_150"}) {
        const json& runs = wake[key]["runs"];
        const double roshko = wake[key]["roshko"];
        const json& last = runs.back();
        EXPECT_GE(last["periods"].get<int>(), 4) << key;
        EXPECT_NEAR(last["strouhal"].get<double>(), roshko, 0.2 * roshko) << key;
        const json& probe = last["probe"];
        const auto [low, high] = std::minmax_element(probe.begin(), probe.end());
        EXPECT_LT(low->get<double>(), -0.1) << key;
        EXPECT_GT(high->get<double>(), 0.1) << key;
    }
}

class ValidateQuick : public Cli {};

TEST_F(ValidateQuick, EveryStudyMeetsTheSeedsClaims) {
    const fs::path out = mDir / "out";
    const RunResult r =
        run("validate --quick --out " + out.string() + " --cache-dir " + mCache.string());
    ASSERT_EQ(r.status, 0) << r.err;
    const json results = json::parse(testing::slurp(out / "results.json"));
    const std::string html = testing::slurp(out / "report.html");
    checkProgressAndReport(results, r.err, html);
    EXPECT_NE(html.find("Mantaflow, the outside check, was not run: --quick"), std::string::npos);
    checkConvergence(results);
    checkIntegrators(results);
    checkMhd(results);
    checkCoefficients(results);
    checkResolution(results);
    checkWake(results);
    checkSpeed(results);
    checkReducedVsFull(results);
    checkLansAlpha(results);
}

}  // namespace
}  // namespace modeflow
