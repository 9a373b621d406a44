// `rockface import PROJECT FILE [--visit N | --new-visit [--geologist NAME]] [--columns x,y,z,...]
//  [--offset E,N,Z] [--frame survey|local] [--view-from E,N,Z] [--gcp FILE |
//  --pole X1,Y1,Z1,X2,Y2,Z2|auto [--range-pole M] [--azimuth DEG --reference-line
//  X1,Y1,Z1,X2,Y2,Z2 [--declination DEG]]]`: a point cloud
// or a mesh made elsewhere (PLY, OBJ, PCD, XYZ / TXT / CSV / ASC, PTS, PTX,
// LAS) becomes a visit's 3D image (firmware-app/import/import_surface.h).
// A refused file stops the verb (exit 2) naming the file and the place, with
// nothing stored. The options are read into the request by import_options.h.
#include <filesystem>
#include <iostream>
#include <memory>

#include "core/common/error.h"
#include "core/common/number_format.h"
#include "firmware-app/cli/verb_registry.h"
#include "firmware-app/import/import_options.h"
#include "firmware-app/import/import_surface.h"

namespace rockface::app {
namespace {

// E N Z to the millimetre, as a surveyor reads them.
std::string survey_words(const Eigen::Vector3d& p) {
  return "E " + format_fixed(p.x(), 3) + " N " + format_fixed(p.y(), 3) + " Z " +
         format_fixed(p.z(), 3);
}

// A point of a local frame in the file's own numbers, as --pole takes them.
std::string local_words(const Eigen::Vector3d& p) {
  return format_fixed(p.x(), 4) + "," + format_fixed(p.y(), 4) + "," + format_fixed(p.z(), 4);
}

VerbRun setup_import(CLI::App& sub) {
  auto o = std::make_shared<ImportOptions>();
  sub.add_option("PROJECT", o->project, "project file (*.rockface); created when missing")
      ->required();
  sub.add_option("FILE", o->file,
                 "the 3D image: " + storage::imported_surface_extensions() +
                     " (LAZ and E57 converted first)")
      ->required();
  auto* visit = sub.add_option("--visit", o->visit, "add it to this visit");
  sub.add_flag("--new-visit", o->new_visit, "a new visit for it (the default)")->excludes(visit);
  sub.add_option("--geologist", o->geologist, "the geologist who mapped the new visit, by name")
      ->type_name("NAME");
  sub.add_option("--columns", o->columns,
                 "a text cloud's columns when its header does not name them, e.g. x,y,z,r,g,b "
                 "(- skips a column)");
  sub.add_option("--offset", o->offset,
                 "E,N,Z added to every coordinate: the shift the file was written with");
  sub.add_option("--frame", o->frame,
                 "survey (already scaled and oriented) or local; default: survey when the "
                 "coordinates are beyond 10 km or an offset is given");
  sub.add_option("--view-from", o->view_from,
                 "E,N,Z: a point the surface is seen from (the scanner's station)");
  sub.add_option("--gcp", o->gcp,
                 "a local-frame cloud's ground control points, CSV id,u,v,X,Y,Z (u, v pixels of "
                 "its virtual view, as `replay --gcp` takes them on the left photograph)");
  sub.add_option("--pole", o->pole,
                 "a local-frame cloud's range pole: its lower and upper target's centres in the "
                 "file's coordinates, X1,Y1,Z1,X2,Y2,Z2, or auto: found in the cloud's colours "
                 "(scales and levels it)");
  sub.add_option("--range-pole", o->range_pole,
                 "m between the pole's targets; default: the length typed last in the project");
  sub.add_option("--azimuth", o->azimuth,
                 "with --pole: the compass bearing of --reference-line, degrees (gives north)");
  sub.add_option("--reference-line", o->reference_line,
                 "with --azimuth: the line's two points in the file's coordinates, "
                 "X1,Y1,Z1,X2,Y2,Z2");
  sub.add_option("--declination", o->declination, "degrees, east positive (with --azimuth)");
  return [o] {
    const ImportRequest request = import_request(*o);
    // The file is checked before the project is created or changed.
    if (!std::filesystem::is_regular_file(o->file)) throw InputError(o->file, "no such file");
    // A new project's datum is the file's (import_surface.h): zero here.
    // A project created for a file that is then refused is removed again:
    // a refused import leaves the folder as it was.
    const bool created = !std::filesystem::exists(o->project);
    ImportResult r;
    try {
      storage::ProjectInfo info;
      info.name = std::filesystem::path(o->project).stem().string();
      storage::ProjectStore store = storage::ProjectStore::open_or_create(o->project, info);
      r = import_surface(store, request);
    } catch (...) {
      if (created)
        for (const char* suffix : {"", "-wal", "-shm", "-journal"})
          std::filesystem::remove(o->project + suffix);
      throw;
    }
    std::cout << o->file << ": " << r.format << ", " << r.points << " points";
    if (r.skipped_points) std::cout << " (" << r.skipped_points << " without a return)";
    std::cout << "\n";
    if (r.intensity_as_grey)
      std::cout << "colours: none in the file; its intensity drawn as grey ("
                << intensity_range_words(r) << ", linearly)\n";
    if (r.meshed)
      std::cout << "meshed: " << r.triangles << " triangles "
                << (r.round_meshing.empty() ? "over the best plane" : "as " + r.round_meshing)
                << ", point spacing " << r.point_spacing_m * 1000 << " mm, " << r.unused_points
                << " points in no triangle (holes kept, never bridged)\n";
    else
      std::cout << "mesh: " << r.triangles << " triangles of the file\n";
    if (r.noise_sigma_m)
      std::cout << "scatter normal to the surface: " << *r.noise_sigma_m * 1000
                << " mm (taken as its depth precision)\n";
    if (r.frame == "survey") {
      std::cout << "survey coordinates: registered by the scanner's registration; file offset "
                << survey_words(r.file_datum) << "\n";
      if (r.project_datum_set)
        std::cout << "the project's datum is now the file's: " << survey_words(r.project_datum)
                  << "\n";
    } else if (r.control_points > 0) {
      std::cout << "a local frame registered by " << r.control_points
                << " ground control points: scale " << r.control_scale << ", rms "
                << r.control_rms_m * 1000 << " mm\n";
      if (r.project_datum_set)
        std::cout << "the project's datum is now the control points': "
                  << survey_words(r.project_datum) << "\n";
    } else if (r.pole_length_m) {
      std::cout << "a local frame scaled and levelled by the range pole (" << *r.pole_length_m
                << " m between its targets)";
      if (r.pole_found)
        std::cout << ", its targets found in the cloud's colours at "
                  << local_words(r.pole_found->lower) << " and "
                  << local_words(r.pole_found->upper);
      if (r.north_rotation_deg)
        std::cout << ", north by the compass line (turned " << *r.north_rotation_deg << " deg)";
      else
        std::cout << ", no north: +y is the view's direction, not north";
      std::cout << "\n";
    } else {
      std::cout << "a local frame: not scaled or oriented until control points are picked on it\n";
    }
    std::cout << "virtual view " << r.view_width << " x " << r.view_height << " px, seen "
              << r.view_side << "\n";
    std::cout << "stored in " << o->project << ": visit " << r.visit << ", model " << r.model
              << "\n";
    return 0;
  };
}

const VerbRegistrar import_verb{
    "import", "a point cloud or mesh made elsewhere as a visit's 3D image", setup_import};

}  // namespace
}  // namespace rockface::app
