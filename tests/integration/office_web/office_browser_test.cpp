// The office's pages in a real browser (issue 46): headless Chromium over
// WebDriver against `rockface office serve` on a real PostgreSQL server
// holding two tablets' synced visits. Log in, open the drive, open a
// visit, see its 3D face drawn and turn it, fetch its field report; the
// same walk at a phone's width. Skipped only when Chromium is absent.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <numbers>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <tuple>
#include <vector>

#include <Eigen/Core>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "core/common/progress.h"
#include "core/tunnel/drive_sets.h"
#include "firmware-app/office/office_workflows.h"
#include "storage/office/sync_push.h"
#include "storage/project/project_sqlite.h"
#include "storage/project/project_store.h"
#include "tests/integration/office_web/blocks_table_truth.h"
#include "tests/integration/office_web/office_site.h"
#include "tests/storage/office/office_environment.h"
#include "tests/storage/office/tablet_projects.h"
#include "tests/support/cli_run.h"
#include "tests/support/web_driver.h"

// Last: <resolv.h>, which httplib.h includes, defines the macro _res that
// Eigen uses as a parameter name.
#include <httplib.h>

namespace rockface::office_web_test {
namespace {

using nlohmann::json;

// Pixels of the canvas region that differ from the renderer's clear colour
// (#20242a) by more than a little in some channel, as a fraction.
double drawn_fraction(const cv::Mat& shot, const json& rect) {
  const cv::Rect r(rect[0].get<int>(), rect[1].get<int>(), rect[2].get<int>(), rect[3].get<int>());
  const cv::Rect in = r & cv::Rect(0, 0, shot.cols, shot.rows);
  if (in.area() == 0) return 0;
  int drawn = 0;
  for (int y = in.y; y < in.y + in.height; ++y)
    for (int x = in.x; x < in.x + in.width; ++x) {
      const cv::Vec3b p = shot.at<cv::Vec3b>(y, x);
      // 24 of 255: above the antialiasing and JPEG-free PNG noise of a
      // flat background (which is exactly the clear colour).
      if (std::abs(p[0] - 0x2a) > 24 || std::abs(p[1] - 0x24) > 24 || std::abs(p[2] - 0x20) > 24)
        ++drawn;
    }
  return static_cast<double>(drawn) / in.area();
}

double changed_fraction(const cv::Mat& a, const cv::Mat& b, const json& rect) {
  const cv::Rect r(rect[0].get<int>(), rect[1].get<int>(), rect[2].get<int>(), rect[3].get<int>());
  const cv::Rect in = r & cv::Rect(0, 0, std::min(a.cols, b.cols), std::min(a.rows, b.rows));
  if (in.area() == 0) return 0;
  int changed = 0;
  for (int y = in.y; y < in.y + in.height; ++y)
    for (int x = in.x; x < in.x + in.width; ++x) {
      const cv::Vec3b p = a.at<cv::Vec3b>(y, x), q = b.at<cv::Vec3b>(y, x);
      if (std::abs(p[0] - q[0]) + std::abs(p[1] - q[1]) + std::abs(p[2] - q[2]) > 30) ++changed;
    }
  return static_cast<double>(changed) / in.area();
}

void expect_no_raw_data(const std::string& text, const std::string& page) {
  for (const char* raw : {"{\"", "\":", "undefined", "NaN", "[object", "null", "chainage_text",
                          "verdict_kind", "dipdir"})
    EXPECT_EQ(text.find(raw), std::string::npos) << page << " shows raw data: " << raw;
}

std::string run(const std::string& command) {
  std::string out;
  FILE* p = ::popen(command.c_str(), "r");
  if (!p) return out;
  char buffer[4096];
  while (std::size_t n = std::fread(buffer, 1, sizeof buffer, p)) out.append(buffer, n);
  ::pclose(p);
  return out;
}

// Logs in as the office reader and opens the drive of Main drive by clicks;
// `tunnels` (when given) gets the Tunnels page's rows, each cell's text.
void open_drive(WebDriver& d, const OfficeServer& server, json* tunnels = nullptr) {
  d.go(server.origin() + "/");
  d.type(d.wait_for("#role"), "office_reader");
  d.type(d.wait_for("#password"), kOfficePassword);
  d.click(d.wait_for("#login button[type=submit]"));
  d.wait_for("a.tunnel-link");
  if (tunnels)
    *tunnels = d.script(
        "return [...document.querySelectorAll('table tbody tr')].map(r => [...r.cells].map(c "
        "=> c.textContent))");
  d.click(d.element_by_script(
      "return [...document.querySelectorAll('a.tunnel-link')].find(a => a.textContent === "
      "'Main drive')"));
  d.wait_for("table.visits tbody tr");
}

// The truth the pages are checked against: the tablets' own projects that
// the site synced (office_site.cpp), read here with SQLite, not through the
// server or the pages.
namespace truth {

namespace fs = std::filesystem;

// The tablets' project files of a tunnel.
std::vector<fs::path> tablet_files(const std::string& tunnel) {
  if (tunnel == "North adit") return {site().folder / "adit-c.rockface"};
  return {site().folder / "a.rockface", site().folder / "b.rockface"};
}

struct LocalVisit {
  fs::path file;
  std::int64_t id = 0;
};

// The tablet's project and local id of a visit the server names by uuid.
std::optional<LocalVisit> visit_of(const std::string& uuid) {
  for (const auto& file : tablet_files("Main drive")) {
    storage::sqlite::Connection db(file, storage::sqlite::Connection::Access::read_only);
    storage::sqlite::Statement st(db, "SELECT id FROM visit WHERE uuid = ?", "finding a visit");
    st.bind(1, uuid);
    if (st.step()) return LocalVisit{file, st.column_int(0)};
  }
  return std::nullopt;
}

// The geologist the tablet's project names for a visit; none when it
// names none.
std::optional<std::string> geologist(const LocalVisit& v) {
  storage::sqlite::Connection db(v.file, storage::sqlite::Connection::Access::read_only);
  storage::sqlite::Statement st(db, "SELECT geologist FROM visit_geologist WHERE visit_id = ?",
                                "reading the visit's geologist");
  st.bind(1, v.id);
  if (!st.step()) return std::nullopt;
  return st.column_text(0);
}

// Every row of `sql` (one column of doubles per row) on a visit's file,
// the visit's id bound to each "?".
std::vector<std::vector<double>> rows(const LocalVisit& v, const std::string& sql, int columns) {
  storage::sqlite::Connection db(v.file, storage::sqlite::Connection::Access::read_only);
  storage::sqlite::Statement st(db, sql, "reading the tablet's project");
  for (int i = 1; i <= static_cast<int>(std::count(sql.begin(), sql.end(), '?')); ++i)
    st.bind(i, v.id);
  std::vector<std::vector<double>> out;
  while (st.step()) {
    std::vector<double> row;
    for (int c = 0; c < columns; ++c)
      row.push_back(st.is_null(c) ? std::numeric_limits<double>::quiet_NaN() : st.column_double(c));
    out.push_back(row);
  }
  return out;
}

// Where the stereonet (ui/web/stereonet.js: a 260-unit SVG, the net's
// centre at 130, radius 120) puts the pole of a plane: lower hemisphere,
// equal area (Schmidt). The pole of a plane dipping d towards a points to
// a + 180 and lies d from the vertical; equal area puts a line at angle t
// from the vertical at R * sqrt(2) * sin(t / 2) from the centre, north up.
std::pair<double, double> stereonet_place(double dip, double dipdir) {
  constexpr double kDeg = 3.14159265358979323846 / 180.0;
  const double rho = 120.0 * std::sqrt(2.0) * std::sin(dip * kDeg / 2.0);
  const double trend = (dipdir + 180.0) * kDeg;
  return {130.0 + rho * std::sin(trend), 130.0 - rho * std::cos(trend)};
}

// How many of `expected` are drawn in `drawn` (each drawn point used once),
// within `tolerance` SVG units.
std::size_t matched_points(const std::vector<std::pair<double, double>>& expected,
                           const json& drawn, double tolerance) {
  std::vector<bool> used(drawn.size(), false);
  std::size_t found = 0;
  for (const auto& [x, y] : expected)
    for (std::size_t i = 0; i < drawn.size(); ++i) {
      if (used[i]) continue;
      if (std::abs(drawn[i][0].get<double>() - x) <= tolerance &&
          std::abs(drawn[i][1].get<double>() - y) <= tolerance) {
        used[i] = true;
        ++found;
        break;
      }
    }
  return found;
}

// The distance from `p` (the project frame) to the nearest triangle of the
// visit's first 3D image, measured where p projects inside a triangle
// (infinity when it projects into none).
double distance_to_face(const LocalVisit& v, const Eigen::Vector3d& p) {
  storage::OpenOptions read;
  read.read_only = true;
  storage::ProjectStore store = storage::ProjectStore::open(v.file, read);
  const auto models = store.list_visit_models(v.id);
  if (models.empty()) return std::numeric_limits<double>::infinity();
  const storage::Mesh mesh = store.load_model(models.front().id).mesh;
  double best = std::numeric_limits<double>::infinity();
  for (const auto& f : mesh.faces) {
    const Eigen::Vector3d a = mesh.vertices[f[0]], b = mesh.vertices[f[1]], c = mesh.vertices[f[2]];
    const Eigen::Vector3d n = (b - a).cross(c - a);
    if (n.norm() == 0) continue;
    const Eigen::Vector3d u = n.normalized();
    const double off = (p - a).dot(u);
    const Eigen::Vector3d q = p - off * u;
    // Barycentric coordinates of q; a little outside is the triangle's edge.
    const double area = n.norm();
    const double wa = (b - q).cross(c - q).dot(u) / area;
    const double wb = (c - q).cross(a - q).dot(u) / area;
    const double wc = 1.0 - wa - wb;
    if (wa < -1e-6 || wb < -1e-6 || wc < -1e-6) continue;
    best = std::min(best, std::abs(off));
  }
  return best;
}

// The centre of the bounding box of the visit's first 3D image: the
// origin of the mesh frame the browser draws in (office_pages.h).
Eigen::Vector3d face_centre(const LocalVisit& v) {
  storage::OpenOptions read;
  read.read_only = true;
  storage::ProjectStore store = storage::ProjectStore::open(v.file, read);
  const storage::Mesh mesh = store.load_model(store.list_visit_models(v.id).front().id).mesh;
  Eigen::Vector3d lo = mesh.vertices.front(), hi = lo;
  for (const auto& p : mesh.vertices) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  return 0.5 * (lo + hi);
}

}  // namespace truth

struct Walk {
  std::string drive_text, visit_text, visit_uuid, cookie;
  double face_drawn = 0, face_turned = 0;
  int page_width = 0, window_width = 0;
  int photograph_width = 0;  // the first photograph as the page shows it
  // The first photograph's width on the page before and after a click.
  double photograph_shown = 0, photograph_zoomed = 0;
  json tunnels;      // the Tunnels page's rows
  json visit_rows;   // the drive's visits: id, blocks that move, largest, geologist
  json strip_marks;  // the visit strip's marks: visit id, its title's text
  // The visit page's geologist line: its text, and whether it holds only
  // text (no element made of the name's markup).
  std::string visit_geologist;
  bool visit_geologist_is_text = false;
  json stereonet;   // the poles and set means drawn, SVG units
  json rock_mass;   // the Rock mass section's lines (or its note)
  json measured;    // two double-clicks on the 3D face: status, points
  json block_rows;  // the visit's blocks table, each cell's text
  // The 3D face's traces and blocks as three.js draws them (each one's
  // label, material colour and vertices), the stereonet's set means'
  // colours and the face's legend.
  json face_overlays;
};

// Log in, open the drive of Main drive, open the visit with blocks, wait
// for its 3D face, turn it.
Walk walk(const OfficeServer& server, int width, int height) {
  Walk w;
  WebDriver d(width, height);
  open_drive(d, server, &w.tunnels);
  w.visit_rows = d.script(
      "return [...document.querySelectorAll('table.visits tbody tr')].map(r => ({id: "
      "r.querySelector('a.visit-link').getAttribute('href').split('/').pop(), moving: "
      "r.cells[6].textContent, largest: r.cells[7].textContent, geologist: r.cells[[...document."
      "querySelectorAll('table.visits thead th')].findIndex(h => h.textContent === "
      "'Geologist')]?.textContent}))");
  w.strip_marks = d.script(
      "return [...document.querySelectorAll('svg.strip a')].map(a => ({id: "
      "a.getAttribute('href').split('/').pop(), title: a.querySelector('title').textContent}))");
  if (const char* keep = std::getenv("ROCKFACE_OFFICE_WEB_SHOTS"))
    cv::imwrite(std::string(keep) + "/drive-" + std::to_string(width) + ".png", d.screenshot());
  w.drive_text = d.script("return document.body.innerText").get<std::string>();
  EXPECT_TRUE(d.script("return window.rockfaceInjected === undefined && "
                       "document.querySelectorAll('img[src=\"x\"]').length === 0")
                  .get<bool>())
      << "the note's script ran or its markup became elements";
  EXPECT_FALSE(d.alert_open());
  // The visit whose latest analysis has blocks (tablet A's mapped face).
  d.click(d.element_by_script(
      "return [...document.querySelectorAll('table.visits tbody tr')].filter(r => "
      "r.cells[5].textContent !== '0').map(r => r.querySelector('a.visit-link'))[0]"));
  d.wait_for("table.blocks tbody tr", std::chrono::seconds(90));
  d.wait_for("#face[data-drawn=yes]", std::chrono::seconds(60));
  w.visit_uuid = d.script("return location.hash.split('/').pop()").get<std::string>();
  w.visit_text = d.script("return document.body.innerText").get<std::string>();
  {
    const json g = d.script(
        "const p = document.getElementById('visit-geologist'); return p ? [p.textContent, "
        "p.children.length === 0] : ['', false]");
    w.visit_geologist = g[0];
    w.visit_geologist_is_text = g[1];
  }
  w.block_rows = d.script(
      "return [...document.querySelectorAll('table.blocks tbody tr')].map(r => [...r.cells].map(c "
      "=> c.textContent))");
  d.script("document.getElementById('face-canvas').scrollIntoView()");
  // The photograph's texture arrives after the mesh.
  std::this_thread::sleep_for(std::chrono::milliseconds(800));
  const json rect = d.script(
      "const r = document.getElementById('face-canvas').getBoundingClientRect(); return "
      "[Math.round(r.left), Math.round(r.top), Math.round(r.width), Math.round(r.height)]");
  const cv::Mat before = d.screenshot();
  w.face_drawn = drawn_fraction(before, rect);
  w.face_overlays = d.script(
      "const s = document.getElementById('face').faceScene; if (!s) return null; const colour = "
      "(o) => '#' + o.material.color.getHexString(); const points = (o) => "
      "Array.from(o.geometry.getAttribute('position').array); const drawn = (key) => "
      "s.children.filter(o => o.userData[key] !== undefined).map(o => ({label: o.userData[key], "
      "colour: colour(o), points: points(o)})); return {traces: drawn('trace'), blocks: "
      "drawn('block'), sets: [...document.querySelectorAll('svg.stereonet rect[data-set]')].map(r "
      "=> [r.getAttribute('data-set'), r.getAttribute('stroke')]), legend: "
      "[...document.querySelectorAll('#face-legend .legend-item')].map(i => [i.textContent, "
      "i.querySelector('rect').getAttribute('fill')])}");
  // The stereonet's poles and set means, and the rock mass sheet's lines.
  w.stereonet = d.script(
      "const s = document.querySelector('svg.stereonet'); if (!s) return null; return {poles: "
      "[...s.querySelectorAll('circle.pole')].map(c => [+c.getAttribute('cx'), "
      "+c.getAttribute('cy')]), sets: [...s.querySelectorAll('rect')].map(r => "
      "[+r.getAttribute('x') + 5, +r.getAttribute('y') + 5])}");
  w.rock_mass = d.script(
      "const s = [...document.querySelectorAll('section')].find(x => x.querySelector('h2') && "
      "x.querySelector('h2').textContent === 'Rock mass'); if (!s) return null; return "
      "[...s.querySelectorAll('li, p')].map(e => e.textContent)");
  // A distance measured on the face: two double-clicks inside the canvas
  // (the face fills its middle in the first view), as a person makes them.
  w.measured = d.script(
      "const c = document.getElementById('face-canvas'); const r = c.getBoundingClientRect(); "
      "const at = (fx, fy) => c.dispatchEvent(new MouseEvent('dblclick', {bubbles: true, "
      "clientX: r.left + fx * r.width, clientY: r.top + fy * r.height})); at(0.5, 0.5); "
      "at(0.6, 0.56); const h = document.getElementById('face'); return {status: "
      "document.getElementById('face-status').textContent, from: h.dataset.measuredFrom || '', "
      "to: h.dataset.measuredTo || ''}");
  // ROCKFACE_OFFICE_WEB_SHOTS=FOLDER keeps the screenshots for a person to look at.
  if (const char* keep = std::getenv("ROCKFACE_OFFICE_WEB_SHOTS"))
    cv::imwrite(std::string(keep) + "/face-" + std::to_string(width) + ".png", before);
  d.drag(d.wait_for("#face-canvas"), width / 5, 0);
  std::this_thread::sleep_for(std::chrono::milliseconds(500));
  w.face_turned = changed_fraction(before, d.screenshot(), rect);
  // The visit's photographs are fetched from the server as they are shown
  // (its copy on the web server holds none): the first, scrolled to, loads.
  w.photograph_width =
      d.script(
           "const i = document.querySelector('img[alt^=\"photograph\"]'); if (!i) return 0; "
           "i.scrollIntoView(); return new Promise(r => { let n = 0; const t = setInterval(() => "
           "{ if (i.naturalWidth > 0 || ++n > 200) { clearInterval(t); r(i.naturalWidth); } }, "
           "100); })")
          .get<int>();
  // A click on the photograph zooms it (and the page stays as wide as the
  // window, checked below).
  const std::string photo =
      d.element_by_script("return document.querySelector('img[alt^=\"photograph\"]')");
  w.photograph_shown =
      d.script("return document.querySelector('img[alt^=\"photograph\"]').clientWidth")
          .get<double>();
  d.click(photo);
  // The zoom's transition takes 0.2 s.
  std::this_thread::sleep_for(std::chrono::milliseconds(700));
  w.photograph_zoomed =
      d.script("return document.querySelector('img[alt^=\"photograph\"]').clientWidth")
          .get<double>();
  d.click(photo);
  std::this_thread::sleep_for(std::chrono::milliseconds(700));
  w.page_width = d.script("return document.documentElement.scrollWidth").get<int>();
  w.window_width = d.script("return window.innerWidth").get<int>();
  w.cookie = d.cookie("rockface_session");
  return w;
}

void expect_walk(const Walk& w, const std::string& name) {
  EXPECT_NE(w.drive_text.find("Drive of Main drive"), std::string::npos) << name;
  EXPECT_NE(w.drive_text.find("4 visits, 2 tablets"), std::string::npos) << name;
  EXPECT_NE(w.drive_text.find(" m"), std::string::npos) << name << ": chainage without unit";
  EXPECT_NE(w.drive_text.find(kScriptNote), std::string::npos)
      << name << ": the note is shown as the text it is";
  expect_no_raw_data(w.drive_text, name + " drive");
  EXPECT_NE(w.visit_text.find("°"), std::string::npos) << name;
  EXPECT_NE(w.visit_text.find(" mm"), std::string::npos) << name << ": precision without unit";
  EXPECT_NE(w.visit_text.find(" m³"), std::string::npos) << name << ": volume without unit";
  expect_no_raw_data(w.visit_text, name + " visit");
  // The face covers about half the canvas in the first view; a tenth
  // drawn says it is drawn at all, not how well.
  EXPECT_GT(w.face_drawn, 0.1) << name << ": the 3D face is blank";
  // A drag of a fifth of the window turns the face by about 90°: far more
  // than 2 % of the canvas changes.
  EXPECT_GT(w.face_turned, 0.02) << name << ": dragging did not turn the face";
  EXPECT_LE(w.page_width, w.window_width) << name << ": the page is wider than the window";
  // The site's photographs are hundreds of pixels wide: a decoded picture,
  // not a broken image (0).
  EXPECT_GT(w.photograph_width, 100) << name << ": the visit's photograph did not load";
}

// Every point of `drawn` (x y z ...) within `tolerance` of a point of
// `truth` in each coordinate; false when `drawn` is empty.
bool drawn_at(const json& drawn, const std::vector<Eigen::Vector3d>& truth, double tolerance) {
  if (drawn.empty() || drawn.size() % 3 != 0) return false;
  for (std::size_t i = 0; i < drawn.size(); i += 3) {
    const Eigen::Vector3d p(drawn[i].get<double>(), drawn[i + 1].get<double>(),
                            drawn[i + 2].get<double>());
    const bool near = std::any_of(truth.begin(), truth.end(), [&](const Eigen::Vector3d& t) {
      return (p - t).cwiseAbs().maxCoeff() <= tolerance;
    });
    if (!near) return false;
  }
  return true;
}

// The 3D face's "traces coloured by set, blocks by verdict" (issue 46): each
// trace of the visit drawn once, where the tablet measured it, in the colour
// the stereonet gives the set of the joint the geologist assigned it to on
// the tablet (the legend's "no set" colour for a trace of no set); each
// block of its latest analysis drawn once, where the tablet's analysis put
// it, in the legend's colour of its verdict as the tablet stored it
// (finite, removable). The truth is the tablet's own project.
void expect_face_colours(const Walk& w, const truth::LocalVisit& visit, const std::string& name) {
  const json& f = w.face_overlays;
  ASSERT_TRUE(f.is_object()) << name << ": the 3D face's scene is not on the page";
  std::map<std::string, std::string> set_colour, legend;
  for (const auto& s : f["sets"]) set_colour[s[0].get<std::string>()] = s[1];
  for (const auto& l : f["legend"]) legend[l[0].get<std::string>()] = l[1];
  // The legend shows each set in the stereonet's colour.
  for (const auto& [set, colour] : set_colour)
    EXPECT_EQ(legend[set], colour) << name << ": set " << set << " in the legend";
  ASSERT_TRUE(legend.count("no set")) << name << ": " << f["legend"].dump();

  storage::OpenOptions read;
  read.read_only = true;
  storage::ProjectStore store = storage::ProjectStore::open(visit.file, read);
  std::map<std::string, std::string> set_of_joint;
  for (const auto& j : store.list_joints(visit.id)) set_of_joint[j.label] = j.set_label;
  const Eigen::Vector3d centre = truth::face_centre(visit);
  // The page sends points to the millimetre (office_pages.cpp), drawn as
  // float32 a few tens of metres from the face's centre (1e-5 m at most).
  constexpr double kPoint = 0.0005 + 1e-5;
  std::set<std::string> set_colours_drawn;
  int traces = 0, of_no_set = 0;
  for (const auto& m : store.list_measurements(visit.id)) {
    if (m.kind != storage::Measurement::Kind::trace) continue;
    ++traces;
    const auto set = set_of_joint.find(m.joint_label);
    const std::string set_label = set == set_of_joint.end() ? std::string() : set->second;
    const std::string expected = set_label.empty() ? legend["no set"] : set_colour[set_label];
    ASSERT_FALSE(expected.empty()) << name << ": set " << set_label << " is not on the stereonet";
    of_no_set += set_label.empty() ? 1 : 0;
    if (!set_label.empty()) set_colours_drawn.insert(expected);
    std::vector<Eigen::Vector3d> points;
    for (const auto& p : m.points) points.push_back(p - centre);
    int drawn = 0;
    for (const auto& t : f["traces"]) {
      if (t["label"] != m.label) continue;
      ++drawn;
      EXPECT_EQ(t["colour"], expected)
          << name << ": trace " << m.label << " (set " << (set_label.empty() ? "none" : set_label)
          << ") drawn in the wrong colour";
      EXPECT_TRUE(drawn_at(t["points"], points, kPoint))
          << name << ": trace " << m.label << " is not drawn where the tablet measured it";
    }
    EXPECT_EQ(drawn, 1) << name << ": trace " << m.label << " drawn " << drawn << " times";
  }
  EXPECT_EQ(f["traces"].size(), static_cast<std::size_t>(traces)) << name;
  // The test data (tests/storage/office/tablet_projects.cpp) gives the
  // walked visit traces of two sets and of none.
  EXPECT_GE(set_colours_drawn.size(), 2u) << name << ": the visit's traces are of one set only";
  EXPECT_GT(of_no_set, 0) << name;

  const Eigen::Vector3d datum = store.project().datum;
  storage::sqlite::Connection db(visit.file, storage::sqlite::Connection::Access::read_only);
  storage::sqlite::Statement st(db,
                                "SELECT label, finite, removable, report_json FROM block WHERE "
                                "analysis_id = (SELECT max(id) FROM analysis WHERE visit_id = ?)",
                                "reading the tablet's blocks");
  st.bind(1, visit.id);
  std::set<std::string> verdicts;
  int blocks = 0;
  while (st.step()) {
    ++blocks;
    const std::string label = st.column_text(0);
    const std::string verdict = st.column_int(1) == 0   ? "infinite"
                                : st.column_int(2) != 0 ? "removable"
                                                        : "keyed";
    verdicts.insert(verdict);
    ASSERT_TRUE(legend.count(verdict)) << name << ": no " << verdict << " in the legend";
    std::vector<Eigen::Vector3d> vertices;
    // Stored absolute (the datum added) to 1e-5 m.
    const json stored = json::parse(st.column_text(3));
    for (const auto& v : stored["vertices"])
      vertices.push_back(
          Eigen::Vector3d(v[0].get<double>(), v[1].get<double>(), v[2].get<double>()) - datum -
          centre);
    int drawn = 0;
    for (const auto& b : f["blocks"]) {
      if (b["label"] != label) continue;
      ++drawn;
      EXPECT_EQ(b["colour"], legend[verdict])
          << name << ": block " << label << " (" << verdict << ") drawn in the wrong colour";
      EXPECT_TRUE(drawn_at(b["points"], vertices, kPoint + 1e-5))
          << name << ": block " << label
          << " is not drawn where the tablet's analysis put it: " << b["points"].dump()
          << " against " << stored["vertices"].dump();
    }
    EXPECT_EQ(drawn, 1) << name << ": block " << label << " drawn " << drawn << " times";
  }
  EXPECT_EQ(f["blocks"].size(), static_cast<std::size_t>(blocks)) << name;
  EXPECT_EQ(verdicts.size(), 3u) << name << ": the visit's blocks do not have every verdict";
}

// The bullets of the pages each checked against the synced tablets'
// projects (namespace truth): the Tunnels page's last visit and drive
// length, the drive's largest removable block and blocks that move, the
// stereonet, the rock mass sheet, a distance measured on the 3D face, the
// photographs zoomable.
void expect_pages_against_the_synced_data(const Walk& w, const std::string& name) {
  // Tunnels: each tunnel's visits, last visit and the drive mapped (first
  // to last placed visit).
  ASSERT_EQ(w.tunnels.size(), 2u) << name << ": " << w.tunnels.dump();
  for (const auto& row : w.tunnels) {
    ASSERT_EQ(row.size(), 4u) << name << ": " << row.dump();
    const std::string tunnel = row[0];
    int visits = 0;
    std::string last;
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (const auto& file : truth::tablet_files(tunnel)) {
      storage::sqlite::Connection db(file, storage::sqlite::Connection::Access::read_only);
      storage::sqlite::Statement v(db, "SELECT started_at FROM visit", "reading the visits");
      while (v.step()) {
        ++visits;
        last = std::max(last, v.column_text(0));
      }
      storage::sqlite::Statement p(db, "SELECT chainage FROM visit_placement", "placements");
      while (p.step()) {
        lo = std::min(lo, p.column_double(0));
        hi = std::max(hi, p.column_double(0));
      }
    }
    EXPECT_EQ(row[1], std::to_string(visits)) << name << ": visits of " << tunnel;
    EXPECT_EQ(row[2], last) << name << ": the last visit of " << tunnel;
    double length = 0, from = 0, to = 0;
    const std::string shown = row[3];
    ASSERT_EQ(std::sscanf(shown.c_str(), "%lf m (ch %lf m to %lf m)", &length, &from, &to), 3)
        << name << ": the drive mapped of " << tunnel << " reads \"" << shown << "\"";
    // Shown to the decimetre: half of it is the rounding.
    EXPECT_NEAR(length, hi - lo, 0.05 + 1e-9) << name << ": the drive length of " << tunnel;
    EXPECT_NEAR(from, lo, 0.05 + 1e-9) << name << ": " << tunnel;
    EXPECT_NEAR(to, hi, 0.05 + 1e-9) << name << ": " << tunnel;
  }

  // The drive: each visit's largest removable block (of its latest
  // analysis) and its blocks that move (removable, with a mode).
  ASSERT_FALSE(w.visit_rows.empty()) << name;
  int with_blocks = 0;
  for (const auto& row : w.visit_rows) {
    const auto v = truth::visit_of(row["id"]);
    ASSERT_TRUE(v) << name << ": visit " << row["id"] << " is in no tablet's project";
    const auto blocks = truth::rows(
        *v,
        "SELECT volume_m3, removable, mode NOT IN ('none', '') FROM block WHERE analysis_id = "
        "(SELECT max(id) FROM analysis WHERE visit_id = ?)",
        3);
    double largest = 0;
    int moving = 0;
    for (const auto& b : blocks) {
      if (b[1] != 0) largest = std::max(largest, b[0]);
      if (b[1] != 0 && b[2] != 0) ++moving;
    }
    EXPECT_EQ(row["moving"], std::to_string(moving)) << name << ": blocks that move";
    const std::string shown = row["largest"];
    if (largest == 0) {
      EXPECT_EQ(shown, "–") << name << ": a visit without a removable block";
      continue;
    }
    ++with_blocks;
    double value = 0;
    ASSERT_EQ(std::sscanf(shown.c_str(), "%lf", &value), 1) << name << ": " << shown;
    EXPECT_NE(shown.find(" m³"), std::string::npos) << name << ": " << shown;
    // Three significant digits: half a unit of the third is the rounding.
    const double unit = std::pow(10.0, std::floor(std::log10(largest)) - 2);
    EXPECT_NEAR(value, largest, 0.5 * unit + 1e-12) << name << ": the largest removable block";
  }
  EXPECT_GT(with_blocks, 0) << name << ": no visit of the drive has a removable block";

  // Issue 46: each visit's geologist, as the tablet's own project names it
  // ("not recorded" where it names none), in the visits' table and in the
  // title of its mark on the strip, as text (the site names one
  // "O'Brien <b>"); and on the visit's page.
  std::set<std::string> names_shown;
  std::size_t marks_checked = 0;
  for (const auto& row : w.visit_rows) {
    const auto v = truth::visit_of(row["id"]);
    ASSERT_TRUE(v) << name;
    const std::string expected = truth::geologist(*v).value_or("not recorded");
    const json shown = row.contains("geologist") ? row["geologist"] : json();
    ASSERT_TRUE(shown.is_string()) << name << ": no Geologist column: " << row.dump();
    EXPECT_EQ(shown, expected) << name << ": visit " << row["id"];
    names_shown.insert(expected);
    for (const auto& mark : w.strip_marks) {
      if (mark["id"] != row["id"]) continue;
      ++marks_checked;
      EXPECT_NE(mark["title"].get<std::string>().find(", geologist " + expected + ","),
                std::string::npos)
          << name << ": the strip's mark of visit " << row["id"] << ": " << mark["title"];
    }
  }
  EXPECT_EQ(names_shown, (std::set<std::string>{"O'Brien <b>", "Anna Berger", "not recorded"}))
      << name << ": the site names two geologists and leaves a visit without";
  // Every placed visit has its mark on the strip: the site's visits but
  // tablet A's mapped face, which is not placed (office_site.cpp).
  EXPECT_GE(marks_checked, 3u) << name << ": " << w.strip_marks.dump();
  {
    const auto walked = truth::visit_of(w.visit_uuid);
    ASSERT_TRUE(walked) << name;
    EXPECT_EQ(w.visit_geologist, "Geologist: " + truth::geologist(*walked).value_or("not recorded"))
        << name;
    EXPECT_TRUE(w.visit_geologist_is_text) << name << ": the name's markup became an element";
  }

  const auto visit = truth::visit_of(w.visit_uuid);
  ASSERT_TRUE(visit) << name;
  // The stereonet: one pole per joint (the visit's sets are stored) or per
  // plane measured (they are clustered on the server), each where equal
  // area puts it; the stored sets' means too.
  ASSERT_TRUE(w.stereonet.is_object()) << name << ": no stereonet on the visit's page";
  const auto sets = truth::rows(*visit, "SELECT dip, dipdir FROM joint_set WHERE visit_id = ?", 2);
  const auto poles =
      sets.empty() ? truth::rows(*visit,
                                 "SELECT dip, dipdir FROM measurement WHERE visit_id = ? AND dip "
                                 "IS NOT NULL AND dipdir IS NOT NULL",
                                 2)
                   : truth::rows(*visit, "SELECT dip, dipdir FROM joint WHERE visit_id = ?", 2);
  ASSERT_GE(poles.size(), 2u) << name;
  std::vector<std::pair<double, double>> expected_poles, expected_sets;
  for (const auto& p : poles) expected_poles.push_back(truth::stereonet_place(p[0], p[1]));
  for (const auto& p : sets) expected_sets.push_back(truth::stereonet_place(p[0], p[1]));
  // The page writes each place to a tenth of a unit (toFixed(1)).
  constexpr double kShown = 0.05 + 1e-9;
  EXPECT_EQ(w.stereonet["poles"].size(), poles.size()) << name << ": poles drawn";
  EXPECT_EQ(truth::matched_points(expected_poles, w.stereonet["poles"], kShown), poles.size())
      << name << ": poles not where equal area puts them: " << w.stereonet["poles"].dump();
  if (!sets.empty()) {
    EXPECT_EQ(w.stereonet["sets"].size(), sets.size()) << name << ": set means drawn";
    EXPECT_EQ(truth::matched_points(expected_sets, w.stereonet["sets"], kShown), sets.size())
        << name << ": set means misplaced: " << w.stereonet["sets"].dump();
  }

  // The blocks table against the tablet's own blocks of the visit.
  expect_blocks_table(w.block_rows, visit->file, visit->id, name);
  // The test data (tablet_projects.cpp) gives a failing block its motion
  // after failure: the column above is checked on a value, not only on "–".
  EXPECT_TRUE(std::any_of(w.block_rows.begin(), w.block_rows.end(),
                          [](const json& row) { return row.size() > 8 && row[8] != "–"; }))
      << name << ": no block of the visit shows a motion after failure";
  expect_face_colours(w, *visit, name);

  // The photograph zoomed by a click: at least half as wide again.
  EXPECT_GT(w.photograph_shown, 50) << name;
  EXPECT_GT(w.photograph_zoomed, 1.5 * w.photograph_shown)
      << name << ": a click did not zoom the photograph (" << w.photograph_shown << " -> "
      << w.photograph_zoomed << " px)";

  // The rock mass sheet: what `rockface rockmass` says of the same visit in
  // the tablet's own project (a copy: the verb reads it).
  ASSERT_TRUE(w.rock_mass.is_array()) << name << ": no rock mass section";
  ASSERT_FALSE(w.rock_mass.empty()) << name;
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() /
      ("rockface-office-rockmass-" + std::to_string(::getpid()) + "-" + name);
  std::filesystem::create_directories(dir);
  std::filesystem::copy_file(visit->file, dir / "tablet.rockface",
                             std::filesystem::copy_options::overwrite_existing);
  const test::CliRun cli =
      test::run_rockface("rockmass " + (dir / "tablet.rockface").string() + " --visit " +
                         std::to_string(visit->id) + " --out " + (dir / "rockmass.json").string());
  std::vector<std::string> said;
  {
    std::istringstream in(cli.out);
    for (std::string line; std::getline(in, line);) {
      line.erase(0, line.find_first_not_of(' '));
      said.push_back(line);
    }
  }
  if (cli.exit_code == 0) {
    for (const auto& shown : w.rock_mass) {
      std::string line = shown;
      line.erase(0, line.find_first_not_of(' '));
      EXPECT_TRUE(std::find(said.begin(), said.end(), line) != said.end())
          << name << ": the rock mass sheet shows \"" << line << "\", which `rockface rockmass` "
          << "does not say of the visit:\n"
          << cli.out;
    }
    const bool rmr = std::any_of(w.rock_mass.begin(), w.rock_mass.end(), [](const json& l) {
      return l.get<std::string>().rfind("RMR89", 0) == 0;
    });
    EXPECT_TRUE(rmr) << name << ": no RMR89 on the sheet: " << w.rock_mass.dump();
  } else {
    // No figures for this visit: the page says why, as the verb does.
    ASSERT_EQ(w.rock_mass.size(), 1u) << name << ": " << w.rock_mass.dump();
    const std::string note = w.rock_mass[0];
    ASSERT_EQ(note.rfind("no rock-mass figures: ", 0), 0u) << name << ": " << note;
    EXPECT_NE(cli.err.find(note.substr(22)), std::string::npos)
        << name << ": the page's reason \"" << note << "\" is not the verb's: " << cli.err;
  }
  std::error_code ec;
  if (!::testing::Test::HasFailure()) std::filesystem::remove_all(dir, ec);

  // A distance measured by two double-clicks: both points on the synced
  // face (its frame's origin the face's centre, office_pages.h), the
  // distance shown that between them.
  const std::string status = w.measured.value("status", "");
  double distance = -1;
  ASSERT_EQ(std::sscanf(status.c_str(), "Distance: %lf m", &distance), 1)
      << name << ": no distance after two double-clicks on the face: " << status;
  Eigen::Vector3d from, to;
  {
    std::istringstream a(w.measured.value("from", "")), b(w.measured.value("to", ""));
    a >> from.x() >> from.y() >> from.z();
    b >> to.x() >> to.y() >> to.z();
    ASSERT_TRUE(a && b) << name << ": " << w.measured.dump();
  }
  const Eigen::Vector3d origin = truth::face_centre(*visit);
  // The points come from three.js's ray cast on float32 vertices about a
  // metre from the origin: 1e-7 of a metre; 0.1 mm is far beyond that and
  // far below the face's relief.
  EXPECT_LT(truth::distance_to_face(*visit, from + origin), 1e-4) << name << ": first point";
  EXPECT_LT(truth::distance_to_face(*visit, to + origin), 1e-4) << name << ": second point";
  // Shown to the millimetre.
  EXPECT_NEAR(distance, (to - from).norm(), 0.0005 + 1e-9) << name;
  EXPECT_GT((to - from).norm(), 0.01) << name << ": the two clicks measured one point";
}

TEST(OfficeWebBrowser, LaptopWalkAndTheFieldReport) {
  if (!WebDriver::available()) GTEST_SKIP() << "chromium and chromium-driver are not installed";
  OfficeServer server;
  const Walk w = walk(server, 1280, 900);
  expect_walk(w, "laptop");
  expect_pages_against_the_synced_data(w, "laptop");

  // The report, made on demand from the browser's session.
  httplib::Client c("127.0.0.1", server.port());
  c.set_read_timeout(std::chrono::seconds(120));
  const httplib::Headers auth = {{"Cookie", "rockface_session=" + w.cookie}};
  const std::string q = "?tunnel=Main%20drive&visit=" + w.visit_uuid;
  const auto visit = c.Get(("/api/visit" + q).c_str(), auth);
  ASSERT_TRUE(visit);
  ASSERT_EQ(visit->status, 200) << visit->body;
  const json v = json::parse(visit->body);
  ASSERT_FALSE(v["blocks"].empty());
  const auto pdf = c.Get(("/api/visit/report.pdf" + q).c_str(), auth);
  ASSERT_TRUE(pdf);
  ASSERT_EQ(pdf->status, 200) << pdf->body;
  ASSERT_EQ(pdf->body.rfind("%PDF", 0), 0u);
  const std::string file = site().folder.string() + "/report.pdf";
  std::ofstream(file, std::ios::binary) << pdf->body;
  const std::string text = run("pdftotext -layout " + file + " -");
  for (const auto& b : v["blocks"])
    EXPECT_NE(text.find(b["label"].get<std::string>()), std::string::npos)
        << "block " << b["label"] << " is not in the report";
  for (const auto& b : v["blocks"])
    EXPECT_NE(w.visit_text.find(b["label"].get<std::string>()), std::string::npos);
  // The exports, as downloads.
  const auto exports = c.Get(("/api/visit/exports" + q).c_str(), auth);
  ASSERT_TRUE(exports);
  ASSERT_EQ(exports->status, 200) << exports->body;
  const json files = json::parse(exports->body)["files"];
  ASSERT_FALSE(files.empty());
  const std::string first = files[0]["name"];
  const auto download = c.Get(("/api/visit/export" + q + "&name=" + first).c_str(), auth);
  ASSERT_TRUE(download);
  EXPECT_EQ(download->status, 200);
  EXPECT_FALSE(download->body.empty());
  const auto traversal = c.Get(("/api/visit/export" + q + "&name=../../report.pdf").c_str(), auth);
  ASSERT_TRUE(traversal);
  EXPECT_EQ(traversal->status, 404);
}

TEST(OfficeWebBrowser, PhoneWalk) {
  if (!WebDriver::available()) GTEST_SKIP() << "chromium and chromium-driver are not installed";
  OfficeServer server;
  const Walk w = walk(server, 390, 844);
  EXPECT_EQ(w.window_width, 390) << "the page is seen at a phone's width";
  expect_walk(w, "phone");
  expect_pages_against_the_synced_data(w, "phone");
}

// The drive's rounds (RMR89 / Q, the support class, over- and underbreak),
// two visits side by side, and the visit's developed view: in the browser,
// and their data checked against what each must be.
TEST(OfficeWebBrowser, TheRoundsTwoVisitsSideBySideAndTheReportsPictures) {
  if (!WebDriver::available()) GTEST_SKIP() << "chromium and chromium-driver are not installed";
  OfficeServer server;
  WebDriver d(1280, 900);
  open_drive(d, server);
  auto text = [&] { return d.script("return document.body.innerText").get<std::string>(); };
  // The rounds come after the drive, and their over- and underbreak as the
  // server measures it in the background: the table fills in, no reload.
  d.wait_for("table.rounds tbody tr", std::chrono::seconds(90));
  d.wait_for("#rounds-status.rounds-done", std::chrono::seconds(180));
  const int placed = d.script(
                          "return [...document.querySelectorAll('table.visits tbody tr')].filter(r "
                          "=> r.cells[1].textContent !== 'not placed').length")
                         .get<int>();
  EXPECT_EQ(placed, 3) << "tablet A's mapped face is not placed in the tunnel";
  EXPECT_EQ(d.script("return document.querySelectorAll('table.rounds tbody tr').length").get<int>(),
            placed)
      << "one round per placed visit";
  const std::string drive = text();
  EXPECT_NE(drive.find("Support decided"), std::string::npos);
  // The sample's 3D images see the face, not the walls: each round's over-
  // and underbreak is unknown, and said so, never shown as zero (issue 38).
  const int unknown =
      d.script(
           "return [...document.querySelectorAll('table.rounds tbody tr')].filter(r "
           "=> r.cells[5].textContent.startsWith('unknown: ')).length")
          .get<int>();
  EXPECT_EQ(unknown, placed) << drive;
  EXPECT_EQ(drive.find("0.00 m³"), std::string::npos) << "an unseen round shown as no overbreak";
  expect_no_raw_data(drive, "drive with rounds");

  // Tablet A's two visits (its first, with sets, and its mapped face).
  const json ids = d.script(
      "return [...document.querySelectorAll('table.visits tbody tr')].filter(r => "
      "r.cells[3].textContent === 'tablet_a').map(r => "
      "r.querySelector('a.visit-link').getAttribute('href').split('/').pop())");
  ASSERT_EQ(ids.size(), 2u) << ids.dump();
  const std::string a = ids[0], b = ids[1];
  d.script("location.hash = '#/compare/Main%20drive/" + a + "/" + b + "'");
  d.wait_for("table.compare-sets", std::chrono::seconds(60));
  const std::string compared = text();
  EXPECT_NE(compared.find("Two visits side by side"), std::string::npos);
  EXPECT_NE(compared.find("verdicts changed"), std::string::npos);
  expect_no_raw_data(compared, "two visits");
  if (const char* keep = std::getenv("ROCKFACE_OFFICE_WEB_SHOTS"))
    cv::imwrite(std::string(keep) + "/compare.png", d.screenshot());

  httplib::Client c("127.0.0.1", server.port());
  c.set_read_timeout(std::chrono::seconds(120));
  const httplib::Headers auth = {{"Cookie", "rockface_session=" + d.cookie("rockface_session")}};
  auto get_json = [&](const std::string& path) {
    const auto r = c.Get(path.c_str(), auth);
    EXPECT_TRUE(r && r->status == 200) << path << ": " << (r ? r->body : "no answer");
    return r && r->status == 200 ? json::parse(r->body) : json::object();
  };
  auto report = [&](const std::string& visit) {
    return get_json("/api/visit?tunnel=Main%20drive&visit=" + visit);
  };
  // Every set and block of the two accounted for once: matched, vanished
  // (not found again) or new.
  const json ab = get_json("/api/compare?tunnel=Main%20drive&a=" + a + "&b=" + b);
  const json va = report(ab["earlier"]["id"]), vb = report(ab["later"]["id"]);
  std::size_t matched = 0, vanished = 0, fresh = 0;
  for (const auto& set : ab["sets"]) {
    const std::string state = set["state"];
    matched += state == "matched";
    vanished += state == "vanished";
    fresh += state == "new";
    if (state == "matched") {
      EXPECT_GE(set["change_deg"].get<double>(), 0.0);
      // kSameSetDeg (visit_comparison.h): no match farther apart.
      EXPECT_LE(set["change_deg"].get<double>(), 25.0);
    }
  }
  EXPECT_EQ(matched + vanished, va["sets"].size());
  EXPECT_EQ(matched + fresh, vb["sets"].size());
  std::size_t blocks_earlier = 0, blocks_later = 0;
  for (const auto& k : ab["blocks"]) {
    blocks_earlier += k["earlier"] != "–";
    blocks_later += k["later"] != "–";
  }
  EXPECT_EQ(blocks_earlier, va["blocks"].size());
  EXPECT_EQ(blocks_later, vb["blocks"].size());
  // Who mapped each visit, as the tablet named them (truth::geologist),
  // shown as text beside each: tablet A's name holds markup. Tablet B's two
  // (its first named, its second not) through the same answer the page
  // draws from, each on its side.
  auto named = [](const std::string& id) {
    const auto v = truth::visit_of(id);
    EXPECT_TRUE(v) << "visit " << id << " is not in the tablets' files";
    return v ? truth::geologist(*v).value_or("not recorded") : std::string("?");
  };
  for (const char* side : {"earlier", "later"})
    EXPECT_EQ(d.script("const s = document.getElementById(`compare-geologist-${arguments[0]}`); "
                       "return s && s.children.length === 0 ? s.textContent : null",
                       json::array({side})),
              "geologist: " + named(ab[side]["id"]))
        << side;
  std::vector<std::string> of_b;
  const json drive_now = get_json("/api/drive?tunnel=Main%20drive");
  for (const auto& v : drive_now["visits"])
    if (v["tablet"] == "tablet_b") of_b.push_back(v["id"]);
  ASSERT_EQ(of_b.size(), 2u);
  const json b_pair = get_json("/api/compare?tunnel=Main%20drive&a=" + of_b[0] + "&b=" + of_b[1]);
  std::set<std::string> b_names;
  for (const char* side : {"earlier", "later"}) {
    EXPECT_EQ(b_pair[side]["geologist"], named(b_pair[side]["id"])) << side;
    b_names.insert(named(b_pair[side]["id"]));
  }
  EXPECT_EQ(b_names, (std::set<std::string>{"Anna Berger", "not recorded"}))
      << "tablet B's visits were named by one geologist and by none (office_site.cpp)";
  // A visit against itself: every set matched unchanged, every block found
  // where it was with its verdict.
  const json same = get_json("/api/compare?tunnel=Main%20drive&a=" + b + "&b=" + b);
  ASSERT_EQ(same["sets"].size(), vb["sets"].size());
  for (const auto& set : same["sets"]) {
    EXPECT_EQ(set["state"], "matched");
    // The same mean pole twice: the angle is rounding in acos, far below
    // the shown whole degree.
    EXPECT_NEAR(set["change_deg"].get<double>(), 0.0, 1e-3);
  }
  ASSERT_EQ(same["blocks"].size(), vb["blocks"].size());
  for (const auto& k : same["blocks"]) {
    EXPECT_EQ(k["state"], "same verdict");
    EXPECT_EQ(k["moved"], "0 cm");
  }

  // The range pole on tablet A's faces: its targets in the mesh's frame
  // (the mesh's origin, float64 in its header, subtracted) and its length.
  // (Tablet A's mapped face is measured on its first visit's 3D image.)
  const bool later_has_face = vb.value("has_face", false);
  const std::string pole_visit = ab[later_has_face ? "later" : "earlier"]["id"];
  {
    const json pole = (later_has_face ? vb : va)["pole"];
    ASSERT_TRUE(pole.is_object()) << (later_has_face ? vb : va).dump().substr(0, 300);
    EXPECT_EQ(pole["length"], "2.000 m");
    const auto mesh =
        c.Get(("/api/visit/mesh?tunnel=Main%20drive&visit=" + pole_visit).c_str(), auth);
    ASSERT_TRUE(mesh && mesh->status == 200 && mesh->body.size() > 40);
    double origin[3];
    std::memcpy(origin, mesh->body.data() + 16, sizeof origin);
    const json targets = json::parse(kPoleTargets);
    for (int t = 0; t < 2; ++t)
      for (int k = 0; k < 3; ++k)
        // The overlay is rounded to the millimetre (office_pages.cpp).
        EXPECT_NEAR(pole["targets"][t][k].get<double>() + origin[k], targets[t][k].get<double>(),
                    0.0005 + 1e-9)
            << "target " << t << " axis " << k;
  }
  d.script("location.hash = '#/visit/Main%20drive/" + pole_visit + "'");
  d.wait_for("#face[data-drawn=yes]", std::chrono::seconds(60));
  EXPECT_EQ(
      d.script("return document.getElementById('face').dataset.pole || ''").get<std::string>(),
      "yes")
      << "the range pole is not drawn on the 3D face";
  // The face's legend names it with its length, beside its orange swatch.
  EXPECT_EQ(d.script("const i = [...document.querySelectorAll('#face-legend .legend-item')].find(i "
                     "=> i.textContent === 'range pole (2.000 m)'); return i ? "
                     "i.querySelector('rect').getAttribute('fill') : ''")
                .get<std::string>(),
            "#ff8c00")
      << "the legend does not show the range pole";

  // The field report's pictures, as PNG: served for a visit whose report
  // has them, refused with the reason for one whose has not (the sample's
  // 3D images see the face, not the walls: no developed view).
  const json all_ids = d.script(
      "return [...document.querySelectorAll('table.visits tbody tr')].map(r => "
      "r.querySelector('a.visit-link').getAttribute('href').split('/').pop())");
  std::string with_wedges;
  int pictures = 0;
  for (const auto& id : all_ids) {
    const json v = report(id);
    for (const char* which : {"developed", "wedges"}) {
      const bool has = which == std::string("developed")
                           ? v["tunnel"].value("has_developed_view", false)
                           : v["wedges"].value("has_picture", false);
      const auto r = c.Get(("/api/visit/picture?tunnel=Main%20drive&which=" + std::string(which) +
                            "&visit=" + id.get<std::string>())
                               .c_str(),
                           auth);
      ASSERT_TRUE(r);
      if (!has) {
        EXPECT_EQ(r->status, 404) << which << " of " << id;
        continue;
      }
      ++pictures;
      ASSERT_EQ(r->status, 200) << which << " of " << id << ": " << r->body;
      EXPECT_EQ(r->get_header_value("Content-Type"), "image/png");
      const cv::Mat shown =
          cv::imdecode(std::vector<std::uint8_t>(r->body.begin(), r->body.end()), cv::IMREAD_COLOR);
      EXPECT_GT(shown.cols, 100) << which << ": a picture, not a placeholder";
      if (which == std::string("wedges") && with_wedges.empty()) with_wedges = id;
    }
  }
  // The sample site's visits have neither picture (no walls in view, no
  // wedge analysis stored): `pictures` counts those served when one has.
  RecordProperty("pictures_served", pictures);
  if (with_wedges.empty()) return;
  d.script("location.hash = '#/visit/Main%20drive/" + with_wedges + "'");
  d.wait_for("#picture-wedges", std::chrono::seconds(60));
  EXPECT_TRUE(d.script("const i = document.getElementById('picture-wedges'); return new "
                       "Promise(r => { const ok = () => r(i.naturalWidth > 100); if "
                       "(i.complete) ok(); else i.onload = ok; })")
                  .get<bool>())
      << "the wedges' picture did not load in the page";
}

TEST(OfficeWebBrowser, AVisitSyncedWhileTheDriveIsOpenAppearsWithoutAReload) {
  if (!WebDriver::available()) GTEST_SKIP() << "chromium and chromium-driver are not installed";
  const Site s = fresh_site();
  OfficeServer server(s, 30);
  WebDriver d(1280, 900);
  open_drive(d, server);
  auto text = [&] { return d.script("return document.body.innerText").get<std::string>(); };
  ASSERT_NE(text().find("4 visits, 2 tablets"), std::string::npos);
  // A mark in the page's memory: a reload would lose it.
  d.script("window.rockfaceStillHere = true");
  office_test::TabletProject more;
  more.name = "tablet B, second project";
  more.seed = 3;
  more.visits = 1;
  more.first_chainage = 112;
  office_test::make_tablet_project(s.folder / "c.rockface", more);
  NoProgress none;
  storage::office::sync_project(s.folder / "c.rockface",
                                office_test::as_role(s.database, "tablet_b"), {}, none);
  // The page asks every 4 s; 20 s leaves room for a loaded machine.
  bool shown = false;
  for (int i = 0; i < 100 && !shown; ++i) {
    shown = text().find("5 visits, 2 tablets") != std::string::npos;
    if (!shown) std::this_thread::sleep_for(std::chrono::milliseconds(200));
  }
  EXPECT_TRUE(shown) << "the newly synced visit did not appear";
  EXPECT_TRUE(d.script("return window.rockfaceStillHere === true").get<bool>())
      << "the page was reloaded";
}

// A tunnel driven from more than one face (issue 46: "filter by date,
// heading, tablet"): tablet B's first visit was named as taken at the south
// portal with `rockface place --heading` before the tablet synced
// (office_site.cpp); the drive lists each visit's heading ("—" for none)
// and the heading filter keeps that visit alone, or every other one.
TEST(OfficeWebBrowser, TheDriveIsFilteredByTheHeadingAVisitWasTakenAt) {
  if (!WebDriver::available()) GTEST_SKIP() << "chromium and chromium-driver are not installed";
  OfficeServer server;
  WebDriver d(1280, 900);
  open_drive(d, server);
  // [heading, tablet] of each row of the visits' table.
  auto rows = [&] {
    return d.script(
        "return [...document.querySelectorAll('table.visits tbody tr')].map(r => "
        "[r.cells[2].textContent, r.cells[3].textContent])");
  };
  const json all = rows();
  ASSERT_GE(all.size(), 3u) << all.dump();
  int south = 0;
  for (const auto& r : all) {
    if (r[0] == "South portal") {
      ++south;
      EXPECT_EQ(r[1], "tablet_b") << all.dump();
    } else {
      EXPECT_EQ(r[0], "—") << "a visit named no heading is listed without one: " << all.dump();
    }
  }
  EXPECT_EQ(south, 1) << all.dump();
  auto filter = [&](const std::string& heading, std::size_t expected) {
    d.script(
        "const s = document.querySelector('#filter-heading'); s.value = arguments[0]; "
        "s.dispatchEvent(new Event('change'));",
        json::array({heading}));
    // The drive is drawn again from the server, filtered.
    const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    json got = rows();
    while (got.size() != expected && std::chrono::steady_clock::now() < until) {
      std::this_thread::sleep_for(std::chrono::milliseconds(200));
      got = rows();
    }
    return got;
  };
  const json only_south = filter("South portal", 1);
  ASSERT_EQ(only_south.size(), 1u) << only_south.dump();
  EXPECT_EQ(only_south[0][0], "South portal");
  EXPECT_EQ(only_south[0][1], "tablet_b");
  const json unnamed = filter("—", all.size() - 1);
  ASSERT_EQ(unnamed.size(), all.size() - 1) << unnamed.dump();
  for (const auto& r : unnamed) EXPECT_EQ(r[0], "—") << unnamed.dump();
  EXPECT_EQ(filter("", all.size()).size(), all.size()) << "every heading again";
  expect_no_raw_data(d.script("return document.body.innerText").get<std::string>(),
                     "drive by heading");
}

// A plane's unit normal from its dip and dip direction (degrees; x east,
// y north, z up), written out here rather than taken from the code under
// test.
Eigen::Vector3d normal_of(const DipAndDirection& o) {
  const double dip = o.dip_deg * std::numbers::pi / 180, dd = o.dipdir_deg * std::numbers::pi / 180;
  return {std::sin(dip) * std::sin(dd), std::sin(dip) * std::cos(dd), std::cos(dip)};
}

// The sets designed along the drive (office_site.h), found in the page's
// table of sets (rows: name, last sighting, flags, events) by the
// orientation and chainage they were put in at: the turning set is new
// where it first came and turns where its dip was made steeper, by the
// angle put in; the steady set carries no flag, and no other set turns.
void expect_the_designed_sets_flagged(const json& rows) {
  const double first = kTabletBChainage, turned = kTabletBChainage + 2.5;
  // The row last seen at `chainage` near `o`: a visit's mean of six planes
  // lies within 0.4 deg of the mean put in (their scatter's offsets,
  // tablet_projects.cpp), shown to the whole degree (0.5 more).
  auto row_of = [&](const DipAndDirection& o, double chainage) -> std::optional<json> {
    for (const auto& row : rows) {
      double ch = 0, dip = 0, dipdir = 0;
      if (std::sscanf(row[1].get<std::string>().c_str(), "ch %lf m: %lf° / %lf°", &ch, &dip,
                      &dipdir) != 3)
        continue;
      if (std::abs(ch - chainage) < 0.05 && std::abs(dip - o.dip_deg) <= 0.9 &&
          std::abs(std::remainder(dipdir - o.dipdir_deg, 360.0)) <= 0.9)
        return row;
    }
    return std::nullopt;
  };
  const std::optional<json> steady = row_of(kSteadySet, turned);
  const std::optional<json> turning = row_of(kTurnsTo, turned);
  ASSERT_TRUE(steady) << "no set last seen at ch " << turned << " near the steady set's "
                      << kSteadySet.dip_deg << "/" << kSteadySet.dipdir_deg << ": " << rows.dump();
  ASSERT_TRUE(turning) << "no set last seen at ch " << turned << " near the turned set's "
                       << kTurnsTo.dip_deg << "/" << kTurnsTo.dipdir_deg << ": " << rows.dump();
  EXPECT_EQ((*steady)[2], "–") << "the steady set is flagged: " << steady->dump();
  const std::string flags = (*turning)[2], events = (*turning)[3];
  EXPECT_NE(flags.find("new"), std::string::npos) << turning->dump();
  EXPECT_NE(flags.find("turns"), std::string::npos) << turning->dump();
  // New where it was first put in (tablet A's visit at ch 102 has it not).
  char at[80];
  std::snprintf(at, sizeof at, "appears at chainage %.2f", first);
  EXPECT_NE(events.find(at), std::string::npos) << events;
  // It turns between the two visits by the angle between the two means put
  // in (12 deg); the visits' means, scattered alike about them, differ
  // from it by less than 0.2 deg, and the page shows a tenth.
  const double put_in =
      std::acos(normal_of(kTurnsFrom).dot(normal_of(kTurnsTo))) * 180 / std::numbers::pi;
  std::snprintf(at, sizeof at, "turns between chainage %.2f and %.2f: ", first, turned);
  const std::size_t turn = events.find(at);
  ASSERT_NE(turn, std::string::npos) << events;
  const double shown = std::stod(events.substr(turn + std::strlen(at)));
  EXPECT_NEAR(shown, put_in, 0.25) << events;
  for (const auto& row : rows) {
    if (row == *turning) continue;
    EXPECT_EQ(row[2].get<std::string>().find("turns"), std::string::npos)
        << "a set that was not turned is flagged as turning: " << row.dump();
  }
}

// The drive's sets (issue 46: "the sets along the drive (dip / dip
// direction against chainage, new and turning sets flagged)"): the page's
// table and both charts against the sets the server tracks along the drive
// (`rockface drive postgresql://...`, app::server_drive), which OfficeSync
// (tests/storage/office/sync_pull_test.cpp) finds equal to the pulled
// project's drive.
TEST(OfficeWebBrowser, TheDrivesSetsAreTheSetsTheServerTracksAlongTheDrive) {
  if (!WebDriver::available()) GTEST_SKIP() << "chromium and chromium-driver are not installed";
  OfficeServer server;
  WebDriver d(1280, 900);
  open_drive(d, server);
  const tunnel::DriveSets truth =
      app::server_drive(office_test::as_role(site().database, "office_reader"), "Main drive");
  ASSERT_FALSE(truth.tracks.empty()) << "the site's drive has no sets to show";

  // The table: one row per track, its name, last point and flags.
  const json rows = d.script(
      "const s = [...document.querySelectorAll('section')].find(x => x.querySelector('h2') && "
      "x.querySelector('h2').textContent === 'Sets along the drive'); if (!s) return null; "
      "return [...s.querySelectorAll('tbody tr')].map(r => [...r.cells].map(c => "
      "c.textContent))");
  ASSERT_TRUE(rows.is_array()) << "no table of the sets along the drive";
  ASSERT_EQ(rows.size(), truth.tracks.size()) << rows.dump();
  for (std::size_t i = 0; i < truth.tracks.size(); ++i) {
    const tunnel::SetTrack& t = truth.tracks[i];
    const json& row = rows[i];
    ASSERT_EQ(row.size(), 4u) << row.dump();
    EXPECT_EQ(row[0], "set " + std::to_string(t.id));
    const std::string flags = row[2];
    EXPECT_EQ(flags.find("new") != std::string::npos, t.appears) << row.dump();
    EXPECT_EQ(flags.find("turns") != std::string::npos, t.turns) << row.dump();
    EXPECT_EQ(flags.find("vanishes") != std::string::npos, t.vanishes) << row.dump();
    ASSERT_FALSE(t.points.empty());
    const tunnel::TrackPoint& last = t.points.back();
    const std::string seen = row[1];
    double chainage = 0, dip = 0, dipdir = 0;
    ASSERT_EQ(std::sscanf(seen.c_str(), "ch %lf m: %lf° / %lf°", &chainage, &dip, &dipdir), 3)
        << "set " << t.id << "'s last sighting reads \"" << seen << "\"";
    // Chainage to the decimetre, orientations to the whole degree: half of
    // each is the rounding.
    EXPECT_NEAR(chainage, last.chainage, 0.05 + 1e-9) << seen;
    EXPECT_NEAR(dip, last.dip_deg, 0.5 + 1e-9) << seen;
    EXPECT_NEAR(dipdir, last.dipdir_deg, 0.5 + 1e-9) << seen;
    EXPECT_NE(seen.find(" planes)"), std::string::npos) << seen;
  }
  expect_the_designed_sets_flagged(rows);

  // The charts (ui/web/drive.js: a 900 x 170 viewBox, the plot from x 48
  // to 888 over the chainage of the placed visits and the tracks' points,
  // y from 22 (top of the range) to 142 (its foot)): each track's points
  // where its dip (0-90°) and dip direction (0-360°) put them, a turned
  // point drawn larger.
  double c0 = std::numeric_limits<double>::infinity(), c1 = -c0;
  for (const auto& file : truth::tablet_files("Main drive")) {
    storage::sqlite::Connection db(file, storage::sqlite::Connection::Access::read_only);
    storage::sqlite::Statement p(db, "SELECT chainage FROM visit_placement", "placements");
    while (p.step()) {
      c0 = std::min(c0, p.column_double(0));
      c1 = std::max(c1, p.column_double(0));
    }
  }
  for (const auto& t : truth.tracks)
    for (const auto& p : t.points) {
      c0 = std::min(c0, p.chainage);
      c1 = std::max(c1, p.chainage);
    }
  if (c1 - c0 < 1) {
    c0 -= 0.5;
    c1 += 0.5;
  }
  for (const auto& [label, lo, hi] : {std::tuple{"Dip of each set", 0.0, 90.0},
                                      std::tuple{"Dip direction of each set", 0.0, 360.0}}) {
    const json dots = d.script(
        "const g = document.querySelector(`svg.chart[aria-label=\"${arguments[0]}\"]`); if (!g) "
        "return null; return [...g.querySelectorAll('circle')].map(c => [+c.getAttribute('cx'), "
        "+c.getAttribute('cy'), +c.getAttribute('r')])",
        json::array({label}));
    ASSERT_TRUE(dots.is_array()) << "no chart \"" << label << "\"";
    std::size_t points = 0;
    std::vector<bool> used(dots.size(), false);
    for (const auto& t : truth.tracks)
      for (const auto& p : t.points) {
        ++points;
        const double value = std::string(label) == "Dip of each set" ? p.dip_deg : p.dipdir_deg;
        const double x = 48 + (p.chainage - c0) / (c1 - c0) * 840;
        const double y = 22 + (1 - (value - lo) / (hi - lo)) * 120;
        bool found = false;
        for (std::size_t i = 0; i < dots.size() && !found; ++i) {
          // The page computes the same doubles; 1e-6 of a unit is their
          // rounding through the attribute's text.
          if (used[i] || std::abs(dots[i][0].get<double>() - x) > 1e-6 ||
              std::abs(dots[i][1].get<double>() - y) > 1e-6)
            continue;
          used[i] = found = true;
          EXPECT_EQ(dots[i][2].get<double>(), p.turned ? 6.0 : 4.0)
              << label << ": set " << t.id << " at ch " << p.chainage << " turned " << p.turned;
        }
        EXPECT_TRUE(found) << label << ": set " << t.id << " at ch " << p.chainage << " (" << value
                           << "°) is not where the chart must put it: " << dots.dump();
      }
    EXPECT_EQ(dots.size(), points) << label;
    // One point turned along the drive: the turning set's at its turn.
    EXPECT_EQ(std::count_if(dots.begin(), dots.end(), [](const json& c) { return c[2] == 6.0; }), 1)
        << label << ": " << dots.dump();
  }
}

}  // namespace
}  // namespace rockface::office_web_test
