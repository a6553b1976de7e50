// Plugins: C++ classes compiled into fxview that an effect names in a `plugin` block
// (docs/plugins.md). A plugin reads the effect's parameters and textures, runs (on a worker thread
// in the viewer) with progress and cancellation, and writes its results into the effect's
// parameters. An effect can only name a built-in type; it never loads native code.
#pragma once
#include <atomic>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "effect/parameter_values.hpp"
#include "image/image.hpp"

namespace fxview::plugin {

// Thrown from Reporter::update when the user cancelled; run() lets it through.
struct Cancelled : Error {
    Cancelled() : Error("cancelled") {}
};

// Where a running plugin is.
struct Progress {
    double fraction = 0;  // 0..1
    std::string stage;
    std::map<std::string, std::vector<double>> parameters;  // its outputs' current values (live preview)
    double cost = 0;                                         // the quantity it minimises, for the error curve
};

// How a plugin reports progress and learns that it was cancelled.
class Reporter {
public:
    Reporter(std::function<void(const Progress&)> report = {}, const std::atomic<bool>* cancel = nullptr)
        : report_(std::move(report)), cancel_(cancel) {}
    // Throws Cancelled when cancellation was asked for; otherwise forwards the progress.
    void update(const Progress& progress) const {
        if (cancel_ && cancel_->load()) throw Cancelled();
        if (report_) report_(progress);
    }

private:
    std::function<void(const Progress&)> report_;
    const std::atomic<bool>* cancel_;
};

struct Result {
    std::map<std::string, std::vector<double>> parameters;  // written into the effect's values
    std::string technique;                                  // selected afterwards; empty: keep the current one
    bool converged = true;
    std::vector<std::string> warnings;
    std::vector<double> cost_per_iteration;  // the error curve
    std::vector<std::string> summary;        // lines for the user: what was found, how well
    std::map<std::string, double> numbers;   // figures for --json (cost, iterations, ...)
    std::optional<image::FloatImage> preview;  // linear RGB, e.g. measured | model | difference
    std::string preview_caption;
};

class Plugin {
public:
    virtual ~Plugin() = default;
    virtual std::string name() const = 0;
    virtual std::string type() const = 0;
    virtual std::string description() const = 0;   // one line for the UI and `plugin list`
    virtual std::vector<std::string> inputs() const = 0;   // parameters and samplers it reads
    virtual std::vector<std::string> outputs() const = 0;  // parameters it writes
    // The technique that shows its outputs (selected while it runs and after); empty: the current one.
    virtual std::string technique() const { return {}; }
    // Runs on a snapshot of the values; must not touch anything shared (it may run on a worker
    // thread while the effect is edited or reloaded). `user_file`, when not empty, replaces the file
    // of its first input: a file the user named (CLI --data, the viewer's field), so the effect's
    // file-access policy, which guards what effect files name, does not apply to it. Throws Error
    // for bad data, Cancelled.
    virtual Result run(const effect::ParameterValues& values, const Reporter& reporter, const std::string& user_file = {}) const = 0;
};

// The plugin an effect declares, checked against the effect (targets exist and have the right
// types): EffectError at the declaration's file and line otherwise. `texture_dirs`: where the
// effect's texture files are searched.
std::unique_ptr<Plugin> create(const effect::Effect& effect, const effect::PluginDeclaration& declaration,
                               const std::vector<std::string>& texture_dirs);
std::vector<std::unique_ptr<Plugin>> create_all(const effect::Effect& effect, const std::vector<std::string>& texture_dirs);
// The types fxview has.
std::vector<std::string> types();

// Writes the result's parameters into `values` where the effect still has them with the same size
// (after a reload the effect may have changed) and the value passes the rule of every value
// (effect::value_problem); returns, for each one it could not write, "NAME: why".
std::vector<std::string> apply(const effect::Effect& effect, effect::ParameterValues& values, const Result& result);

}  // namespace fxview::plugin
