#pragma once
// A visit imported in a local frame, scaled and levelled after the import by
// the range pole's two targets tapped on the tablet's 3D view (issue 43):
// the cloud had no photograph for the pole to be found in, and neither its
// colours (`import --pole auto`) nor a pick in CloudCompare gave the
// targets. The visit's 3D images are carried by the similarity `import
// --pole` would have applied (import_range_pole.h: the targets `length_m`
// apart, the pole vertical, the lower target at the origin), and their
// registration says so ("targets_from": "tapped on the tablet's 3D view").
#include <string>

#include "firmware-app/import/import_range_pole.h"
#include "storage/project/project_store.h"

namespace rockface::app {

struct ImportScaledByPole {
  double scale = 1;  // metres per unit of the file's frame
  std::string note;  // "scaled and levelled by the range pole (2.000 m between its targets)"
};

// `pole`: the targets' centres as stored (the imported visit's frame, which
// is the file's while nothing registered it), lower first. Throws InputError
// naming the visit (no 3D image, not an import in a local frame, scaled or
// registered already, measured or placed in its present frame) or the pole
// (its length, its targets at one point).
ImportScaledByPole scale_import_by_pole(storage::ProjectStore& store, storage::RecordId visit_id,
                                        const ImportPole& pole, double length_m);

}  // namespace rockface::app
