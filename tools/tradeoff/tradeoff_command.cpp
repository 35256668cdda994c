#include "tools/tradeoff/tradeoff_command.h"

#include <cmath>
#include <iomanip>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>

#include "core/system/atomic_file.h"
#include "core/image_io/rgb_image_input.h"
#include "core/scene_file/scene_loader.h"
#include "tools/tradeoff/tradeoff_fit.h"
#include "tools/tradeoff/tradeoff_sweep.h"

namespace wt {

namespace {

struct TradeoffOptions {
    std::string scene_path, reference_path;
    double budget_seconds = 120.0;
    std::vector<int> spp;  // empty: chosen from the budget
    std::vector<std::string> knobs;  // empty: all
    int repeats = 3;
    double target_rmse = 0.08;
    std::optional<int> width, height;
    std::optional<uint64_t> seed;
    int threads = 0;
    std::optional<std::string> csv_path, fits_csv_path;
    bool quiet = false;
};

CLI::App* add_options(CLI::App& app, TradeoffOptions& o) {
    CLI::App* cmd = app.add_subcommand("tradeoff", "Sweep the knobs that trade render time for error against a reference");
    cmd->add_option("scene", o.scene_path, "Scene file (JSON)")->required()->check(CLI::ExistingFile);
    cmd->add_option("--reference", o.reference_path, "Reference image (linear EXR) of the scene's resolution")->required();
    cmd->add_option("--budget", o.budget_seconds,
                    "Render time to spend on the whole sweep, in seconds: picks the spp ladder (4, 16, 64, ...)")
        ->check(CLI::PositiveNumber);
    cmd->add_option("--spp", o.spp, "Explicit spp ladder instead of the budget's, e.g. 4,16,64")
        ->delimiter(',')->check(CLI::Range(1, 1 << 20));
    cmd->add_option("--knobs", o.knobs, "Knobs to sweep, comma-separated (default: all)")->delimiter(',');
    cmd->add_option("--repeats", o.repeats, "Renders per measurement; the median time is kept")->check(CLI::Range(1, 100));
    cmd->add_option("--target-rmse", o.target_rmse, "Report the time each configuration needs to reach this RMSE")
        ->check(CLI::PositiveNumber);
    cmd->add_option("--width", o.width, "Override the scene's width")->check(CLI::Range(1, 65536));
    cmd->add_option("--height", o.height, "Override the scene's height")->check(CLI::Range(1, 65536));
    cmd->add_option("--seed", o.seed, "Override the scene's seed (every configuration uses the same one)");
    cmd->add_option("--threads", o.threads, "Worker threads (default: one per hardware thread)")->check(CLI::Range(1, 1024));
    cmd->add_option("--csv", o.csv_path, "Write every measurement: configuration, spp, seconds, rmse, rel_mse, ...");
    cmd->add_option("--fits-csv", o.fits_csv_path, "Write each configuration's fit (what tools/plot_tradeoff.py draws)");
    cmd->add_flag("-q,--quiet", o.quiet, "Print only the table");
    return cmd;
}

// Powers of 4 from 4 spp while the whole sweep's estimated time fits the budget, from a pilot
// render of the base at 4 spp; at least 4 and 16, so every configuration has a fit.
std::vector<int> spp_for_budget(double seconds_at_4, std::size_t configurations, int repeats, double budget) {
    std::vector<int> ladder = {4, 16};
    double per_configuration = seconds_at_4 * (1.0 + 4.0) * repeats;
    while (ladder.back() < (1 << 18)) {
        const double next = per_configuration + seconds_at_4 * (ladder.back() * 4 / 4) * repeats;
        if (next * double(configurations) > budget) break;
        per_configuration = next;
        ladder.push_back(ladder.back() * 4);
    }
    return ladder;
}

std::string seconds_text(double s) {
    if (std::isinf(s)) return "never";
    if (std::isnan(s)) return "n/a";
    std::ostringstream out;
    out << std::setprecision(3) << s;
    return out.str();
}

struct ConfigurationSummary {
    ErrorFit fit;
    double seconds_per_spp = 0.0;       // total median time over total spp: the largest spp dominates
    const Measurement* last = nullptr;  // at the largest spp
    bool on_front = false;              // one of its measurements is on the Pareto front

    double spp_to(double target_rmse) const { return spp_to_reach(fit, target_rmse); }
    double seconds_to(double target_rmse) const { return spp_to(target_rmse) * seconds_per_spp; }
};

std::string count_text(double spp) {
    if (std::isinf(spp)) return "never";
    if (std::isnan(spp)) return "n/a";
    return std::to_string(std::llround(std::ceil(spp)));
}

void print_table(std::ostream& out, const std::vector<Configuration>& configurations,
                 const std::vector<ConfigurationSummary>& summaries, double target_rmse) {
    const std::string target = "<" + seconds_text(target_rmse) + ")";
    out << std::left << std::setw(30) << "configuration" << std::right << std::setw(6) << "spp" << std::setw(9) << "time(s)"
        << std::setw(10) << "RMSE" << std::setw(10) << "relMSE" << std::setw(11) << "efficiency" << std::setw(8) << "slope"
        << std::setw(12) << "floor_RMSE" << std::setw(17) << ("spp(RMSE" + target) << std::setw(15) << ("t(RMSE" + target)
        << "  pareto\n";
    for (std::size_t i = 0; i < configurations.size(); ++i) {
        const ConfigurationSummary& s = summaries[i];
        const Measurement& m = *s.last;
        const double efficiency = 1.0 / (m.error.rel_mse * m.seconds);
        out << std::left << std::setw(30) << configurations[i].name << std::right << std::setw(6) << m.spp << std::fixed
            << std::setprecision(3) << std::setw(9) << m.seconds << std::defaultfloat << std::setprecision(4)
            << std::setw(10) << m.error.rmse << std::setw(10) << m.error.rel_mse << std::setw(11) << efficiency
            << std::setprecision(3) << std::setw(8) << s.fit.slope << std::setw(12) << std::sqrt(s.fit.floor)
            << std::setw(17) << count_text(s.spp_to(target_rmse)) << std::setw(15) << seconds_text(s.seconds_to(target_rmse))
            << "  " << (s.on_front ? "yes" : "") << "\n";
    }
}

std::string points_csv(const std::vector<Configuration>& configurations, const std::vector<Measurement>& measurements,
                       const std::vector<bool>& front) {
    std::ostringstream csv;
    csv.precision(9);
    csv << "configuration,knob,value,can_bias,spp,seconds,seconds_min,seconds_max,rmse,rel_mse,efficiency,pareto\n";
    for (std::size_t i = 0; i < measurements.size(); ++i) {
        const Measurement& m = measurements[i];
        const Configuration& c = configurations[m.configuration];
        csv << c.name << "," << c.knob << "," << c.value << "," << c.can_bias << "," << m.spp << "," << m.seconds << ","
            << m.seconds_min << "," << m.seconds_max << "," << m.error.rmse << "," << m.error.rel_mse << ","
            << 1.0 / (m.error.rel_mse * m.seconds) << "," << int(front[i]) << "\n";
    }
    return csv.str();
}

std::string fits_csv(const std::vector<Configuration>& configurations, const std::vector<ConfigurationSummary>& summaries,
                     double target_rmse) {
    std::ostringstream csv;
    csv.precision(9);
    csv << "configuration,can_bias,slope,c,floor_mse,variance,seconds_per_spp,target_rmse,spp_to_target,seconds_to_target\n";
    for (std::size_t i = 0; i < configurations.size(); ++i) {
        const ConfigurationSummary& s = summaries[i];
        csv << configurations[i].name << "," << configurations[i].can_bias << "," << s.fit.slope << "," << s.fit.c << ","
            << s.fit.floor << "," << s.fit.variance << "," << s.seconds_per_spp << "," << target_rmse << ","
            << s.spp_to(target_rmse) << "," << s.seconds_to(target_rmse) << "\n";
    }
    return csv.str();
}

int run(TradeoffOptions& o) {
    try {
        std::vector<const Knob*> knobs;
        if (o.knobs.empty())
            for (const Knob& k : tradeoff_knobs()) knobs.push_back(&k);
        for (const std::string& name : o.knobs) knobs.push_back(&tradeoff_knob(name));
        for (const auto& path : {o.csv_path, o.fits_csv_path})
            if (path) check_output_directory(*path);

        SceneDescription description = load_scene_file(o.scene_path);
        if (o.width) description.settings.width = *o.width;
        if (o.height) description.settings.height = *o.height;
        if (o.seed) description.settings.seed = *o.seed;
        const RenderSettings& base = description.settings;
        const RgbImage reference = read_rgb_image(o.reference_path);
        if (reference.width != base.width || reference.height != base.height)
            throw std::runtime_error("--reference " + o.reference_path + ": the reference is " + std::to_string(reference.width) +
                                     "x" + std::to_string(reference.height) + " but the scene renders " +
                                     std::to_string(base.width) + "x" + std::to_string(base.height) +
                                     " (use --width and --height)");

        const std::vector<Configuration> configurations = tradeoff_configurations(base, knobs);
        SweepPlan plan;
        plan.repeats = o.repeats;
        plan.render.threads = o.threads;
        plan.spp = o.spp;
        std::sort(plan.spp.begin(), plan.spp.end());
        plan.spp.erase(std::unique(plan.spp.begin(), plan.spp.end()), plan.spp.end());
        if (plan.spp.size() == 1) throw std::runtime_error("--spp: a fit needs at least two different spp");
        if (plan.spp.empty()) {
            SweepPlan pilot = plan;
            pilot.spp = {4};
            pilot.repeats = 1;
            std::vector<Configuration> base_only(configurations.begin(), configurations.begin() + 1);
            const double seconds_at_4 = run_sweep(description, base_only, pilot, reference, [](const Measurement&) {})[0].seconds;
            plan.spp = spp_for_budget(seconds_at_4, configurations.size(), plan.repeats, o.budget_seconds);
        }
        if (!o.quiet) {
            std::cerr << "wavetrace tradeoff: " << o.scene_path << " " << base.width << "x" << base.height << ", "
                      << configurations.size() << " configurations x spp";
            for (int s : plan.spp) std::cerr << " " << s;
            std::cerr << ", " << plan.repeats << " repeats (median time)\n";
        }

        const std::vector<Measurement> measurements =
            run_sweep(description, configurations, plan, reference, [&](const Measurement& m) {
                if (o.quiet) return;
                std::cerr << "  " << std::left << std::setw(34) << configurations[m.configuration].name << std::right
                          << std::setw(7) << m.spp << " spp " << std::fixed << std::setprecision(3) << m.seconds
                          << " s (" << m.seconds_min << "-" << m.seconds_max << ")  RMSE " << std::defaultfloat
                          << std::setprecision(4) << m.error.rmse << "\n";
            });

        std::vector<TimedError> points;
        for (const Measurement& m : measurements) points.push_back({m.seconds, m.error.rmse * m.error.rmse});
        const std::vector<bool> front = pareto_front(points);
        std::vector<ConfigurationSummary> summaries(configurations.size());
        for (std::size_t i = 0; i < configurations.size(); ++i) {
            std::vector<SampledError> own;
            double seconds = 0.0, spp = 0.0;
            for (std::size_t j = 0; j < measurements.size(); ++j) {
                const Measurement& m = measurements[j];
                if (m.configuration != i) continue;
                own.push_back({double(m.spp), points[j].mse});
                seconds += m.seconds, spp += m.spp;
                summaries[i].last = &m;
                summaries[i].on_front = summaries[i].on_front || front[j];
            }
            summaries[i].fit = fit_error_against_spp(own);
            summaries[i].seconds_per_spp = seconds / spp;
        }

        print_table(std::cout, configurations, summaries, o.target_rmse);
        std::cout << "Pareto front (fastest first):";
        for (std::size_t j = 0; j < measurements.size(); ++j)
            if (front[j]) std::cout << " " << configurations[measurements[j].configuration].name << "@" << measurements[j].spp;
        std::cout << "\n";
        if (o.csv_path) write_text_file_atomically(*o.csv_path, points_csv(configurations, measurements, front));
        if (o.fits_csv_path) write_text_file_atomically(*o.fits_csv_path, fits_csv(configurations, summaries, o.target_rmse));
        return 0;
    } catch (const std::exception& e) {
        std::cerr << "wavetrace: error: " << e.what() << "\n";
        return 1;
    }
}

}  // namespace

Subcommand tradeoff_subcommand(CLI::App& app) {
    auto options = std::make_shared<TradeoffOptions>();
    return {add_options(app, *options), [options] { return run(*options); }};
}

}  // namespace wt
