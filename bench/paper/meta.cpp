// projtrack-bench's meta.json: see meta.hpp.
#include "meta.hpp"

#include <sys/utsname.h>

#include <fstream>
#include <opencv2/core.hpp>
#include <opencv2/core/utility.hpp>
#include <sstream>
#include <string>

#include "machine.hpp"
#include "scene.hpp"
#include "sequence.hpp"

namespace projtrack::bench {
namespace {

using synthetic::kSaneArea;
using synthetic::kSaneCentroid;
using synthetic::SceneModel;

std::string params_json(const Params& p) {
  std::ostringstream o;
  o << "{\"rays\": " << p.rays << ", \"recursion\": " << p.recursion
    << ", \"block_size\": " << p.block_size << ", \"grid_size\": " << p.grid_size
    << ", \"max_iterations\": " << p.max_iterations << ", \"convergence\": " << p.convergence
    << ", \"max_gap\": " << p.max_gap << "}";
  return o.str();
}

std::string scene_model_json() {
  std::ostringstream o;
  o << "{\"blur_sigma\": " << SceneModel::kBlurSigma
    << ", \"noise_sigma\": " << SceneModel::kNoiseSigma
    << ", \"gap_run_min\": " << SceneModel::kGapRunMin
    << ", \"gap_run_max\": " << SceneModel::kGapRunMax
    << ", \"speck_share\": " << SceneModel::kSpeckShare << ", \"strokes\": " << SceneModel::kStrokes
    << ", \"truth_area_tolerance\": " << SceneModel::kTruthAreaTolerance
    << ", \"truth_analytic_tolerance\": " << SceneModel::kTruthAnalyticTolerance
    << ", \"truth_centroid_tolerance\": " << SceneModel::kTruthCentroidTolerance << "}";
  return o.str();
}

// Auto acquisition as the code has it (TrackerParams' defaults) and how the runs judge it.
std::string acquisition_json() {
  const TrackerParams tp;
  std::string strategy = "unknown";
  for (auto [name, s] : kStrategies)
    if (s == tp.strategy) strategy = name;
  std::ostringstream o;
  o << "{\"default_strategy\": \"" << strategy << "\", \"candidates\": " << tp.candidates
    << ", \"frames\": " << kAcquisitionFrames << ", \"sane_centroid\": " << kSaneCentroid
    << ", \"sane_area\": " << kSaneArea << "}";
  return o.str();
}

}  // namespace

void write_meta(const Options& opt, const Params& compared, const Params& defaults, int scenes,
                int inconsistent) {
  std::ofstream o(opt.out + "/meta.json");
  const std::string date = utc_now();
  utsname u{};
  uname(&u);
  o << "{\n  \"command\": \"" << opt.command << "\",\n  \"date\": \"" << date
    << "\",\n  \"quick\": " << (opt.quick ? "true" : "false") << ",\n  \"cpu\": \"" << cpu_model()
    << "\",\n  \"cores\": " << cv::getNumberOfCPUs() << ",\n  \"threads_used\": 1"
    << ",\n  \"kernel\": \"" << u.sysname << ' ' << u.release << "\",\n  \"opencv\": \""
    << CV_VERSION << "\",\n  \"compiler\": \"" << __VERSION__
    << "\",\n  \"seeds_per_scene\": " << opt.seeds << ",\n  \"repetitions\": " << opt.reps
    << ",\n  \"scenes\": " << scenes << ",\n  \"inconsistent_scenes\": " << inconsistent
    << ",\n  \"leak_factor\": " << kLeakFactor << ",\n  \"params\": " << params_json(compared)
    << ",\n  \"defaults\": " << params_json(defaults)
    << ",\n  \"edges\": {\"detector\": \"canny\", \"low\": " << EdgeParams{}.low
    << ", \"high\": " << EdgeParams{}.high << ", \"blur\": " << EdgeParams{}.blur << "}"
    << ",\n  \"scene_model\": " << scene_model_json()
    << ",\n  \"acquisition\": " << acquisition_json() << "\n}\n";
}

}  // namespace projtrack::bench
