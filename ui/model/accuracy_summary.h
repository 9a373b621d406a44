#pragma once
// The accuracy of a 3D image in words, as the Model screen shows it: what
// scaled, levelled and oriented it, how precise a picked point is predicted
// to be, how well the pair was matched, and the residual of the control it
// was registered on — or why there is none ("residual: needs three or more
// targets" when a range pole's two targets only give the scale). Read from
// the registration stored with the model (the reconstruction report, or the
// face registration of a further pair), never shown raw.
#include <string>
#include <vector>

#include "storage/project/project_records.h"

namespace rockface::ui {

struct AccuracyLine {
  std::string title;  // "Scale", "North", "Residual", ...
  std::string value;  // in words, with units
  bool warning = false;
};

std::vector<AccuracyLine> accuracy_lines(const storage::Model& model);

}  // namespace rockface::ui
