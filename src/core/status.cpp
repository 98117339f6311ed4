#include "projtrack/status.hpp"

namespace projtrack {

TrackStatus reported_status(EstimateStatus s) {
  switch (s) {
    case EstimateStatus::Ok:
      return TrackStatus::Ok;
    case EstimateStatus::ReachedBorder:
      return TrackStatus::ReachedBorder;
    case EstimateStatus::CoversFrame:
      return TrackStatus::CoversFrame;
    case EstimateStatus::EmptyImage:
      return TrackStatus::EmptyImage;
    case EstimateStatus::InvalidImage:
      return TrackStatus::InvalidImage;
    case EstimateStatus::InvalidParameters:
      return TrackStatus::InvalidParameters;
    case EstimateStatus::OverBudget:
      return TrackStatus::OverBudget;
    case EstimateStatus::Interrupted:
      return TrackStatus::Interrupted;
    case EstimateStatus::InnerPointOutside:
    case EstimateStatus::InnerPointOnEdge:
      break;
  }
  return TrackStatus::Lost;
}

std::string_view status_name(TrackStatus s) {
  switch (s) {
    case TrackStatus::Ok:
      return "ok";
    case TrackStatus::ReachedBorder:
      return "reached-border";
    case TrackStatus::CoversFrame:
      return "covers-frame";
    case TrackStatus::Lost:
      return "lost";
    case TrackStatus::Searching:
      return "searching";
    case TrackStatus::NoInnerPoint:
      return "no-inner-point";
    case TrackStatus::EmptyImage:
      return "empty-image";
    case TrackStatus::InvalidImage:
      return "invalid-image";
    case TrackStatus::InvalidParameters:
      return "invalid-parameters";
    case TrackStatus::OverBudget:
      return "over-budget";
    case TrackStatus::Occluded:
      return "occluded";
    case TrackStatus::Interrupted:
      return "interrupted";
  }
  return "unknown";
}

std::string_view status_name(EstimateStatus s) {
  switch (s) {
    case EstimateStatus::InnerPointOutside:
      return "inner-point-outside";
    case EstimateStatus::InnerPointOnEdge:
      return "inner-point-on-edge";
    case EstimateStatus::Ok:
    case EstimateStatus::ReachedBorder:
    case EstimateStatus::CoversFrame:
    case EstimateStatus::EmptyImage:
    case EstimateStatus::InvalidImage:
    case EstimateStatus::InvalidParameters:
    case EstimateStatus::OverBudget:
    case EstimateStatus::Interrupted:
      return status_name(reported_status(s));  // the tracker's status reporting it: its name
  }
  return "unknown";
}

}  // namespace projtrack
