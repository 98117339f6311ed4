// What projtrack-speed measures that is not a time: the work frames of ordinary content need, and
// what each method makes of the real clip.
#include <algorithm>
#include <string>
#include <vector>

#include "output.hpp"
#include "projtrack/method.hpp"
#include "projtrack/names.hpp"
#include "projtrack/tracker.hpp"
#include "race.hpp"
#include "sections.hpp"

namespace projtrack::bench {

// Not a time: the work each frame of ordinary content needs (TrackResult::work, a multiple of the
// frame's pixels), with no limit, for both object models and every method (acquisition=auto, the
// element's other defaults); and what the default budget changes there: the frames that run out,
// and those whose outcome (status, centroid, area) differs from the unlimited run's.
void ordinary_work(const Clip& clip) {
  const double pixels = static_cast<double>(clip.width) * clip.height;
  for (ObjectModelKind model : {ObjectModelKind::Flow, ObjectModelKind::Edges}) {
    for (Method method : kAllMethods) {
      TrackerParams unlimited, limited;
      unlimited.model = limited.model = model;
      unlimited.max_work = 0;
      Tracker a, b;
      std::vector<double> work;
      int over = 0, changed = 0;
      for (std::size_t i = 0; i < clip.gray.size(); ++i) {
        const cv::Mat& g = clip.gray[i];
        const ImageView v(g.data, g.cols, g.rows, static_cast<std::ptrdiff_t>(g.step));
        const double t = static_cast<double>(i) / 30;
        const TrackResult ra = a.track(v, EdgeParams{}, t, method, Params{}, unlimited);
        const TrackResult rb = b.track(v, EdgeParams{}, t, method, Params{}, limited);
        work.push_back(static_cast<double>(ra.work) / pixels);
        over += rb.status == TrackStatus::OverBudget;
        changed += ra.status != rb.status || ra.features.centroid.x != rb.features.centroid.x ||
                   ra.features.centroid.y != rb.features.centroid.y ||
                   ra.features.area != rb.features.area;
      }
      std::sort(work.begin(), work.end());
      const std::string what = std::string(nick_of(model)) + " " + std::string(method_name(method));
      row("ordinary_work", &clip, what, "median_x", median(work));
      row("ordinary_work", &clip, what, "p99_x", work[work.size() * 99 / 100]);
      row("ordinary_work", &clip, what, "max_x", work.back());
      row("ordinary_work", &clip, what, "over_budget_frames", over);
      row("ordinary_work", &clip, what, "changed_frames", changed);
      row("ordinary_work", &clip, what, "frames", static_cast<double>(work.size()));
    }
  }
  row("ordinary_work", &clip, "default max-work", "x", TrackerParams{}.max_work);
}

// Not a time: what each method makes of real footage with no ground truth. The tracker (as the
// element runs it, acquisition=auto) over the real clip: frames tracked, refused as leaks, lost
// otherwise, and searching.
void real_clip_statuses(const Clip& clip) {
  for (Method method : kAllMethods) {
    Tracker t;
    TrackerParams tp;
    int tracked = 0, leaks = 0, lost = 0, searching = 0, acquisitions = 0;
    for (std::size_t i = 0; i < clip.gray.size(); ++i) {
      const cv::Mat& g = clip.gray[i];
      const TrackResult r =
          t.track(ImageView(g.data, g.cols, g.rows, static_cast<std::ptrdiff_t>(g.step)),
                  EdgeParams{}, static_cast<double>(i) / 30, method, Params{}, tp);
      acquisitions += r.acquired;
      if (r.status == TrackStatus::Lost) {
        ++(r.detail.find("leak") != std::string::npos ? leaks : lost);
      } else if (r.status == TrackStatus::Searching) {
        ++searching;
      } else if (has_features(r.status)) {
        ++tracked;
      }
    }
    const std::string m(method_name(method));
    row("real_statuses", &clip, m, "tracked", tracked);
    row("real_statuses", &clip, m, "refused_as_leak", leaks);
    row("real_statuses", &clip, m, "lost_otherwise", lost);
    row("real_statuses", &clip, m, "searching", searching);
    row("real_statuses", &clip, m, "acquisitions", acquisitions);
  }
}

}  // namespace projtrack::bench
