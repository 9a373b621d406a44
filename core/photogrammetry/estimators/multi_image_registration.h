#pragma once
// Moved: the registration of several 3D images of one face is a pipeline and
// lives in core/photogrammetry/reconstruction/multi_image_registration.h.
// This forwarding header stays only until storage/reconstruction_report.h and
// firmware-app/replay/replay_more_pairs.h include the new path; then delete it.
#include "core/photogrammetry/reconstruction/multi_image_registration.h"
