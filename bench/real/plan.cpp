#include "plan.hpp"

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <opencv2/imgproc.hpp>
#include <sstream>

#include "variants.hpp"

namespace projtrack::bench {
namespace {

// The comma-separated fields of one CSV line (no quoting: the plan's fields hold no comma).
std::vector<std::string> fields(const std::string& line) {
  std::vector<std::string> out;
  std::istringstream s(line);
  std::string f;
  while (std::getline(s, f, ',')) out.push_back(f);
  if (!line.empty() && line.back() == ',') out.push_back("");
  return out;
}

// The rows of a CSV file as maps from its header's names.
std::vector<std::map<std::string, std::string>> read_csv(const std::string& path) {
  std::ifstream in(path);
  std::string line;
  std::vector<std::map<std::string, std::string>> rows;
  if (!std::getline(in, line)) return rows;
  const std::vector<std::string> header = fields(line);
  while (std::getline(in, line)) {
    const std::vector<std::string> f = fields(line);
    std::map<std::string, std::string> row;
    for (std::size_t k = 0; k < header.size(); ++k) row[header[k]] = k < f.size() ? f[k] : "";
    rows.push_back(row);
  }
  return rows;
}

int as_int(const std::string& s) { return std::atoi(s.c_str()); }

}  // namespace

std::vector<PlanEntry> read_plan(const std::string& dir) {
  std::vector<PlanEntry> plan;
  for (auto& r : read_csv(dir + "/plan.csv")) {
    PlanEntry e;
    e.entry = r["entry"];
    e.clip = r["clip"];
    e.variant = r["variant"];
    e.source = r["source"];
    e.kind = r["kind"];
    e.start = as_int(r["start"]);
    e.frames = as_int(r["frames"]);
    e.step = std::max(1, as_int(r["step"]));
    e.mirror = as_int(r["mirror"]) != 0;
    e.crop = {as_int(r["crop_x"]), as_int(r["crop_y"]), as_int(r["crop_w"]), as_int(r["crop_h"])};
    e.scale = std::atof(r["scale"].c_str());
    e.lighting = r["lighting"];
    plan.push_back(e);
  }
  return plan;
}

std::map<std::string, Starts> read_starts(const std::string& dir) {
  std::map<std::string, Starts> out;
  for (auto& r : read_csv(dir + "/seeds.csv")) {
    Starts& s = out[r["entry"]];
    const Point2i p{as_int(r["x"]), as_int(r["y"])};
    if (r["kind"] == "deepest") s.deepest = p;
    if (r["kind"] == "quarter") s.quarters.push_back(p);
    if (r["kind"] == "box") s.box = Rect{p.x, p.y, as_int(r["w"]), as_int(r["h"])};
  }
  return out;
}

bool same_frames(const Clip& c, const std::string& truth_csv) {
  const auto truth = read_csv(truth_csv);
  if (truth.empty()) return true;
  const std::size_t n = std::min(truth.size(), c.frames.size());
  std::vector<double> x(n), y(n);
  double mx = 0, my = 0;
  for (std::size_t i = 0; i < n; ++i) {
    x[i] = std::atof(truth[i].at("luma_mean").c_str());
    y[i] = cv::mean(c.luma(static_cast<int>(i)))[0];
    mx += x[i] / n;
    my += y[i] / n;
  }
  double sxy = 0, sxx = 0;
  for (std::size_t i = 0; i < n; ++i) {
    sxy += (x[i] - mx) * (y[i] - my);
    sxx += (x[i] - mx) * (x[i] - mx);
  }
  // A flat clip (or one frame) fixes no slope: take the limited-range map's.
  const double slope = sxx > 1e-6 ? sxy / sxx : 219.0 / 255.0;
  if (slope < 0.7 || slope > 1.3) return false;
  for (std::size_t i = 0; i < n; ++i)
    if (std::abs(my + slope * (x[i] - mx) - y[i]) > 1.5) return false;
  return true;
}

namespace {

// A plane cropped to the frame's crop (chroma: the crop at half resolution).
cv::Mat crop_plane(const cv::Mat& m, const cv::Rect& crop, bool chroma) {
  if (!chroma) return m(crop).clone();
  const int x = crop.x / 2, y = crop.y / 2;
  const int w = std::min((crop.width + 1) / 2, m.cols - x);
  const int h = std::min((crop.height + 1) / 2, m.rows - y);
  return m(cv::Rect(x, y, w, h)).clone();
}

I420Frame geometry(const I420Frame& in, const PlanEntry& e) {
  I420Frame f = in.clone();
  cv::Mat* planes[] = {&f.y, &f.u, &f.v};
  for (int p = 0; p < 3; ++p) {
    if (e.mirror) cv::flip(*planes[p], *planes[p], 1);
    const cv::Rect whole(0, 0, in.y.cols, in.y.rows);
    if (e.crop.area() > 0 && e.crop != whole) *planes[p] = crop_plane(*planes[p], e.crop, p > 0);
  }
  if (e.scale != 1) {
    const int w = static_cast<int>(std::lround(f.y.cols * e.scale));
    const int h = static_cast<int>(std::lround(f.y.rows * e.scale));
    cv::resize(f.y, f.y, cv::Size(w, h), 0, 0, cv::INTER_AREA);
    cv::resize(f.u, f.u, cv::Size((w + 1) / 2, (h + 1) / 2), 0, 0, cv::INTER_AREA);
    cv::resize(f.v, f.v, cv::Size((w + 1) / 2, (h + 1) / 2), 0, 0, cv::INTER_AREA);
  }
  return f;
}

}  // namespace

std::unique_ptr<Clip> make_entry(const Clip& source, const PlanEntry& e) {
  auto c = std::make_unique<Clip>();
  c->name = e.entry;
  c->variant = e.variant;
  c->path = source.path;
  c->fps_n = source.fps_n;
  c->fps_d = source.fps_d;
  Lighting light(e.lighting);
  const int n = static_cast<int>(source.frames.size());
  for (int i = e.start; i < n; i += e.step) {
    if (e.frames > 0 && static_cast<int>(c->frames.size()) >= e.frames) break;
    I420Frame f = geometry(source.frames[i], e);
    light.apply(f);
    c->frames.push_back(f);
    c->pts.push_back(source.pts[i]);
  }
  if (!c->frames.empty()) {
    c->width = c->frames[0].y.cols;
    c->height = c->frames[0].y.rows;
  }
  return c;
}

}  // namespace projtrack::bench
