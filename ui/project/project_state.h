#pragma once
// The Project screen's own state: the name of a new project, the visit's
// geologist as typed, the tunnel panel and the sync to the office.
#include <string>

#include "ui/project/geologist_entry.h"
#include "ui/project/import_picker.h"
#include "ui/project/office_panel.h"
#include "ui/project/tunnel_panel.h"

namespace rockface::ui {

struct ProjectScreenState {
  std::string new_project_name = "site";
  TunnelState tunnel;             // the project's tunnel and the round's excavation
  OfficeState office;             // the sync to the office
  ImportPickerState import;       // a 3D image made elsewhere, as a visit (issue 43)
  GeologistEntryState geologist;  // who mapped the visit (issue 46)
};

}  // namespace rockface::ui
