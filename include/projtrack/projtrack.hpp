// libprojtrack: the whole public API in one include, <projtrack/projtrack.hpp>.
#pragma once

#include "color_view.hpp"
#include "edge_detection.hpp"
#include "estimator.hpp"
#include "features.hpp"
#include "geometry.hpp"
#include "image_view.hpp"
#include "method.hpp"
#include "names.hpp"
#include "params.hpp"
#include "pose.hpp"
#include "settings.hpp"
#include "status.hpp"
#include "trace.hpp"
#include "tracker.hpp"
#include "tracker_params.hpp"
#include "work_budget.hpp"
