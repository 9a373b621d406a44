#include "firmware-app/office/web_server.h"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <fstream>
#include <iterator>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <system_error>

#include <opencv2/imgcodecs.hpp>

#include "core/common/error.h"
#include "firmware-app/export/visit_export.h"
#include "firmware-app/office/known_browsers.h"
#include "firmware-app/office/login_throttle.h"
#include "firmware-app/office/office_pages.h"
#include "firmware-app/office/office_pulled_copies.h"
#include "firmware-app/office/office_rounds_worker.h"
#include "firmware-app/office/office_sessions.h"
#include "firmware-app/office/office_shared_cache.h"
#include "firmware-app/office/request_connection.h"
#include "firmware-app/office/test_gate.h"
#include "firmware-app/office/visit_comparison.h"
#include "firmware-app/office/visit_report.h"
#include "firmware-app/office/web_assets.h"
#include "firmware-app/office/web_security.h"
#include "storage/office/connection_pool.h"
#include "storage/office/pg_connection.h"
#include "storage/office/server_blobs.h"
#include "storage/project/project_sqlite.h"
#include "storage/project/project_store.h"

// Last: <resolv.h>, which httplib.h includes, defines the macro _res that
// Eigen uses as a parameter name.
#include <httplib.h>

namespace rockface::app {

namespace fs = std::filesystem;
namespace office = storage::office;
using nlohmann::json;
using office_web::OfficeSession;

namespace {

std::mutex running_lock;
httplib::Server* running = nullptr;

// The decimated face goes first (at most this many triangles, a few
// hundred kB); the full mesh on request.
constexpr std::size_t kFaceTriangles = 40000;

void send_json(httplib::Response& res, const json& body, int status = 200) {
  res.status = status;
  // Invalid UTF-8 in a stored note is replaced, never passed on.
  res.set_content(body.dump(-1, ' ', false, json::error_handler_t::replace),
                  "application/json; charset=utf-8");
}

void send_error(httplib::Response& res, int status, const std::string& message) {
  send_json(res, json{{"error", message}}, status);
}

class OfficeServer {
 public:
  explicit OfficeServer(const OfficeServeOptions& o)
      : options_(o),
        tls_(!o.tls_certificate.empty()),
        pool_(o.server, o.pool_size, o.pool_wait),
        sessions_(o.server, o.session_idle, o.work_folder, pool_),
        cache_(o.work_folder / "shared"),
        rounds_(cache_, pool_, o.log_failure) {
    if (tls_)
      http_ = std::make_unique<httplib::SSLServer>(o.tls_certificate.c_str(), o.tls_key.c_str());
    else
      http_ = std::make_unique<httplib::Server>();
    if (!http_->is_valid())
      throw InputError("--tls", "the certificate or its key cannot be read or do not match");
    // Keep-alive connections each hold a worker while they wait: enough
    // workers for a site office's browsers and the load test's 50 clients.
    http_->new_task_queue = [] { return new httplib::ThreadPool(64); };
    http_->set_payload_max_length(64 * 1024);  // a log-in form, never more
    http_->set_post_routing_handler([this](const httplib::Request& req, httplib::Response& res) {
      for (const auto& [k, v] : office_web::security_headers()) res.set_header(k, v);
      if (req.path.rfind("/api/", 0) == 0) res.set_header("Cache-Control", "no-store");
      if (tls_) res.set_header("Strict-Transport-Security", "max-age=31536000");
    });
    http_->set_error_handler([](const httplib::Request&, httplib::Response& res) {
      if (res.body.empty()) send_error(res, res.status, "not found");
    });
    http_->set_exception_handler(
        [](const httplib::Request&, httplib::Response& res, std::exception_ptr) {
          send_error(res, 500, "the server could not answer this request");
        });
    routes();
  }

  httplib::Server& http() { return *http_; }

 private:
  // The session of the request's cookie, null (and the response set to
  // 401) when there is none or it expired.
  std::shared_ptr<OfficeSession> session_of(const httplib::Request& req, httplib::Response& res) {
    sweep();
    const std::string token = office_web::cookie_value(req.get_header_value("Cookie"),
                                                       office_web::session_cookie_name(tls_));
    auto s = sessions_.find(token);
    if (!s) {
      if (!token.empty()) res.set_header("Set-Cookie", office_web::cleared_session_cookie(tls_));
      send_error(res, 401,
                 "log in first (sessions end after " +
                     std::to_string(sessions_.idle().count() / 60000) + " minutes without use)");
    }
    return s;
  }

  bool cross_site(const httplib::Request& req) const {
    return !office_web::same_origin_request(tls_, req.get_header_value("Host"),
                                            req.get_header_value("Origin"),
                                            req.get_header_value("Sec-Fetch-Site"));
  }

  void sweep() {
    const auto now = std::chrono::steady_clock::now();
    std::lock_guard guard(sweep_lock_);
    if (now - last_sweep_ < std::chrono::seconds(30)) return;
    last_sweep_ = now;
    sessions_.expire();
  }

  // Runs `body(session, db)` under the session's lock, `db` the request's
  // connection (request_connection.h: leased from the pool on its first
  // read, acting as the session's role; a handler gives it back before the
  // work that needs no database); refusals of the reader's rights and bad
  // input become 403 / 404 with the reason, a pool busy past its wait 503
  // with Retry-After. A connection still held goes back to the pool (its
  // transaction rolled back, its role reset) when the request ends.
  template <typename Body>
  void with_session(const httplib::Request& req, httplib::Response& res, Body body) {
    auto s = session_of(req, res);
    if (!s) return;
    std::lock_guard guard(s->lock);
    try {
      office_web::RequestConnection db(pool_, s->role);
      body(*s, db);
    } catch (const office::PoolBusy& e) {
      options_.log_failure(req.path + ": " + e.what());
      res.set_header("Retry-After", "2");
      send_error(res, 503, "the office server is busy: try again in a moment");
    } catch (const InputError& e) {
      send_error(res, 404, e.what());
    } catch (const office::ServerError& e) {
      options_.log_failure(req.path + ": " + e.what());
      if (e.sqlstate() == "42501")
        send_error(res, 403, "this log-in may not read that");
      else
        send_error(res, 503, "the database could not answer: try again");
    } catch (const std::exception& e) {
      options_.log_failure(req.path + ": " + e.what());
      send_error(res, 500, e.what());
    }
  }

  void routes() {
    auto& h = *http_;
    h.Get("/", [](const httplib::Request&, httplib::Response& res) { asset(res, "index.html"); });
    h.Get(R"(/assets/([a-z0-9_\-]+\.(js|css|html)))",
          [](const httplib::Request& req, httplib::Response& res) {
            asset(res, req.matches[1].str());
          });
    h.Get(R"(/three/((build|examples/jsm/controls)/[A-Za-z0-9_.]+\.js))",
          [this](const httplib::Request& req, httplib::Response& res) {
            three(res, req.matches[1].str());
          });

    h.Post("/api/login", [this](const httplib::Request& req, httplib::Response& res) {
      if (cross_site(req)) return send_error(res, 403, "a log-in from another site is refused");
      json body;
      try {
        body = json::parse(req.body);
      } catch (const json::exception&) {
        return send_error(res, 400, "the log-in form is not readable");
      }
      const std::string role = body.value("role", "");
      std::string password = body.value("password", "");
      // A browser that logged in as this role before is held by its own
      // count only: a stranger's guesses at the role do not keep it out.
      const std::string known = office_web::cookie_value(
          req.get_header_value("Cookie"), office_web::known_browser_cookie_name(tls_));
      const bool vouched = known_browsers_.vouches(known, role);
      const int wait = vouched ? throttle_.retry_after_known(known)
                               : throttle_.retry_after(req.remote_addr, role);
      if (wait > 0) {
        std::fill(password.begin(), password.end(), '\0');
        res.set_header("Retry-After", std::to_string(wait));
        return send_error(res, 429,
                          "too many failed log-ins: try again in " + std::to_string(wait) + " s");
      }
      try {
        const std::string token = sessions_.log_in(role, password);
        std::fill(password.begin(), password.end(), '\0');
        auto s = sessions_.find(token);
        res.set_header("Set-Cookie",
                       office_web::session_cookie(tls_, token,
                                                  static_cast<int>(std::max<std::int64_t>(
                                                      1, sessions_.idle().count() / 1000))));
        if (!vouched)
          res.set_header("Set-Cookie",
                         office_web::known_browser_cookie(
                             tls_, known_browsers_.remember(role),
                             static_cast<int>(std::chrono::duration_cast<std::chrono::seconds>(
                                                  office_web::KnownBrowsers::kKept)
                                                  .count())));
        send_json(res, json{{"role", s->role}, {"csrf", s->csrf}});
      } catch (const office_web::LoginUnavailable& e) {
        std::fill(password.begin(), password.end(), '\0');
        options_.log_failure(std::string("log-in: ") + e.what());
        send_error(res, 503, "the database cannot take a log-in now: try again in a moment");
      } catch (const office_web::LoginRefused& e) {
        std::fill(password.begin(), password.end(), '\0');
        if (vouched)
          throttle_.failed_known(known);
        else
          throttle_.failed(req.remote_addr, role);
        send_error(res, 403, e.what());
      }
    });
    h.Post("/api/logout", [this](const httplib::Request& req, httplib::Response& res) {
      if (cross_site(req)) return send_error(res, 403, "a request from another site is refused");
      const std::string token = office_web::cookie_value(req.get_header_value("Cookie"),
                                                         office_web::session_cookie_name(tls_));
      auto s = sessions_.find(token);
      if (!s) return send_error(res, 401, "not logged in");
      if (!office_web::tokens_equal(req.get_header_value("X-Rockface-CSRF"), s->csrf))
        return send_error(res, 403, "the request's token is not this session's");
      sessions_.log_out(token);
      res.set_header("Set-Cookie", office_web::cleared_session_cookie(tls_));
      send_json(res, json{{"ok", true}});
    });
    h.Get("/api/session", [this](const httplib::Request& req, httplib::Response& res) {
      auto s = session_of(req, res);
      if (!s) return;
      send_json(res, json{{"role", s->role}, {"csrf", s->csrf}});
    });
    h.Get("/api/tunnels", [this](const httplib::Request& req, httplib::Response& res) {
      with_session(req, res, [&](OfficeSession&, office_web::RequestConnection& db) {
        send_json(res, office_web::tunnels_page(db.db()));
      });
    });
    h.Get("/api/drive", [this](const httplib::Request& req, httplib::Response& res) {
      with_session(req, res, [&](OfficeSession&, office_web::RequestConnection& db) {
        office_web::DriveFilter f;
        f.from = req.get_param_value("from");
        f.to = req.get_param_value("to");
        f.tablet = req.get_param_value("tablet");
        f.heading = req.get_param_value("heading");
        res.set_content(cache_.drive(db, req.get_param_value("tunnel"), f),
                        "application/json; charset=utf-8");
      });
    });
    h.Get("/api/drive/rounds", [this](const httplib::Request& req, httplib::Response& res) {
      with_session(req, res, [&](OfficeSession& s, office_web::RequestConnection& db) {
        // At once, as far as the rounds are read and measured: the rest in
        // the background (office_rounds_worker.h), the page polls.
        office_web::RoundsCount count;
        const std::string text = rounds_.page(db, req.get_param_value("tunnel"), s.role, &count);
        res.set_header("X-Rockface-Rounds-Measured", std::to_string(count.measured));
        res.set_header("X-Rockface-Rounds-Measuring", std::to_string(count.measuring));
        res.set_content(text, "application/json; charset=utf-8");
      });
    });
    h.Get("/api/stamp", [this](const httplib::Request& req, httplib::Response& res) {
      with_session(req, res, [&](OfficeSession&, office_web::RequestConnection& db) {
        send_json(res, json{{"stamp", cache_.stamp(db, req.get_param_value("tunnel"))}});
      });
    });
    h.Get("/api/visit", [this](const httplib::Request& req, httplib::Response& res) {
      with_visit(req, res, false,
                 [&](OfficeSession&, office_web::RequestConnection&, storage::ProjectStore& store,
                     storage::RecordId id, const DriveFaces* drive) {
                   office_web::CpuSlots::Slot slot(cache_.cpu_slots());
                   const storage::FieldReport report = collect_visit_report(store, id, drive);
                   const Eigen::Vector3d origin = office_web::face_origin(store, id);
                   json page = office_web::visit_page(report, req.get_param_value("visit"), origin);
                   json photos = json::array();
                   for (const auto& c : store.list_captures(id))
                     for (const char* side : {"left", "right"})
                       photos.push_back(json{{"capture", c.id}, {"side", side}});
                   page["photos"] = std::move(photos);
                   const auto models = store.list_visit_models(id);
                   page["has_face"] = !models.empty();
                   if (!models.empty()) {
                     const storage::Model m = store.load_model(models.front().id);
                     if (m.texture_capture_id)
                       page["texture"] =
                           json{{"capture", *m.texture_capture_id}, {"side", m.texture_side}};
                     page["face_triangles"] = std::to_string(m.mesh.faces.size()) + " triangles";
                     page["pole"] = office_web::range_pole_overlay(m, origin);
                   }
                   send_json(res, page);
                 });
    });
    h.Get("/api/compare", [this](const httplib::Request& req, httplib::Response& res) {
      with_session(req, res, [&](OfficeSession&, office_web::RequestConnection& db) {
        const std::string tunnel = req.get_param_value("tunnel");
        // Both visits in one copy, without photographs.
        const auto [a, b] = office_web::pulled_visits(cache_, db, tunnel, req.get_param_value("a"),
                                                      req.get_param_value("b"));
        db.release();  // the reports are put together without the database
        storage::OpenOptions read;
        read.read_only = true;
        storage::ProjectStore store = storage::ProjectStore::open(a.file, read);
        storage::FieldReport ra = collect_visit_report(store, a.visit_id, a.drive);
        storage::FieldReport rb = collect_visit_report(store, b.visit_id, b.drive);
        json page = ra.visit_started_at <= rb.visit_started_at ? office_web::compare_visits(ra, rb)
                                                               : office_web::compare_visits(rb, ra);
        const bool swapped = ra.visit_started_at > rb.visit_started_at;
        page["earlier"]["id"] = req.get_param_value(swapped ? "b" : "a");
        page["later"]["id"] = req.get_param_value(swapped ? "a" : "b");
        send_json(res, page);
      });
    });
    h.Get("/api/visit/mesh", [this](const httplib::Request& req, httplib::Response& res) {
      with_visit(req, res, false,
                 [&](OfficeSession&, office_web::RequestConnection&, storage::ProjectStore& store,
                     storage::RecordId id, const DriveFaces*) {
                   const bool full = req.get_param_value("full") == "1";
                   office_web::FaceMesh m =
                       office_web::face_mesh(store, id, full ? 0 : kFaceTriangles);
                   res.set_header("X-Rockface-Triangles", std::to_string(m.triangles) + " of " +
                                                              std::to_string(m.full_triangles));
                   res.set_content(std::string(m.bytes.begin(), m.bytes.end()),
                                   "application/octet-stream");
                 });
    });
    h.Get("/api/visit/photo", [this](const httplib::Request& req, httplib::Response& res) {
      with_visit(req, res, false,
                 [&](OfficeSession&, office_web::RequestConnection& db,
                     storage::ProjectStore& store, storage::RecordId id, const DriveFaces*) {
                   const std::string side = req.get_param_value("side");
                   if (side != "left" && side != "right") throw InputError("side", "left or right");
                   const storage::RecordId capture =
                       std::stoll("0" + req.get_param_value("capture"));
                   bool of_visit = false;
                   for (const auto& c : store.list_captures(id)) of_visit |= c.id == capture;
                   // A texture may be a capture of an earlier visit of the same project.
                   for (const auto& m : store.list_visit_models(id)) {
                     const storage::Model model = store.load_model(m.id);
                     of_visit |= model.texture_capture_id == capture;
                   }
                   if (!of_visit) throw InputError("capture", "not a photograph of this visit");
                   // The visit's copy holds no photograph: this one comes from the
                   // server, read under the person's role and checked by its hash.
                   const office::ServerPhotograph image = office::read_server_photograph(
                       db.db(), photograph_uuid(store, capture, side));
                   res.set_content(std::string(image.bytes.begin(), image.bytes.end()),
                                   image.format == "png" ? "image/png" : "image/jpeg");
                 });
    });
    h.Get("/api/visit/picture", [this](const httplib::Request& req, httplib::Response& res) {
      with_visit(req, res, false,
                 [&](OfficeSession&, office_web::RequestConnection&, storage::ProjectStore& store,
                     storage::RecordId id, const DriveFaces* drive) {
                   // The field report's own pictures: the round's developed view
                   // (over- and underbreak against the design) and the wedges around
                   // the excavation, as the PDF prints them.
                   const storage::FieldReport report = collect_visit_report(store, id, drive);
                   const std::string which = req.get_param_value("which");
                   cv::Mat picture;
                   if (which == "developed" && report.tunnel)
                     picture = report.tunnel->developed_view;
                   else if (which == "wedges" && report.wedges)
                     picture = report.wedges->picture;
                   else if (which != "developed" && which != "wedges")
                     throw InputError("which", "developed or wedges");
                   if (picture.empty()) throw InputError("which", "this visit has no such picture");
                   std::vector<std::uint8_t> png;
                   cv::imencode(".png", picture, png);
                   res.set_content(std::string(png.begin(), png.end()), "image/png");
                 });
    });
    h.Get("/api/visit/report.pdf", [this](const httplib::Request& req, httplib::Response& res) {
      with_visit(req, res, true,
                 [&](OfficeSession& s, office_web::RequestConnection&, storage::ProjectStore& store,
                     storage::RecordId id, const DriveFaces* drive) {
                   const storage::FieldReport report = collect_visit_report(store, id, drive);
                   const auto pdf = visit_report_pdf(report, s.folder);
                   res.set_header("Content-Disposition", "inline; filename=\"visit-" +
                                                             std::to_string(id) + "-report.pdf\"");
                   res.set_content(std::string(pdf.begin(), pdf.end()), "application/pdf");
                 });
    });
    h.Get("/api/visit/exports", [this](const httplib::Request& req, httplib::Response& res) {
      with_visit(req, res, true,
                 [&](OfficeSession& s, office_web::RequestConnection&, storage::ProjectStore& store,
                     storage::RecordId id, const DriveFaces* drive) {
                   const fs::path dir = exports_folder(s, store, id, drive);
                   json files = json::array();
                   for (const auto& e : fs::directory_iterator(dir))
                     files.push_back(json{{"name", e.path().filename().string()},
                                          {"size", format_size(fs::file_size(e.path()))}});
                   send_json(res, json{{"files", files}});
                 });
    });
    h.Get("/api/visit/export", [this](const httplib::Request& req, httplib::Response& res) {
      with_visit(req, res, true,
                 [&](OfficeSession& s, office_web::RequestConnection&, storage::ProjectStore& store,
                     storage::RecordId id, const DriveFaces* drive) {
                   const fs::path dir = exports_folder(s, store, id, drive);
                   const std::string name = req.get_param_value("name");
                   // Only a name the export wrote: no path reaches the file system.
                   for (const auto& e : fs::directory_iterator(dir)) {
                     if (e.path().filename().string() != name) continue;
                     std::ifstream in(e.path(), std::ios::binary);
                     std::string bytes((std::istreambuf_iterator<char>(in)),
                                       std::istreambuf_iterator<char>());
                     res.set_header("Content-Disposition", "attachment; filename=\"" + name + "\"");
                     res.set_content(std::move(bytes), "application/octet-stream");
                     return;
                   }
                   throw InputError("name", "no such export of this visit");
                 });
    });
  }

  // Runs `body(session, db, store, visit id)` on a copy of the request's
  // visit (office_pulled_copies.h): its photographs in it only when
  // `photographs` (the field report and the exports print them); a page
  // fetches each photograph it shows (/api/visit/photo).
  template <typename Body>
  void with_visit(const httplib::Request& req, httplib::Response& res, bool photographs,
                  Body body) {
    with_session(req, res, [&](OfficeSession& s, office_web::RequestConnection& db) {
      // The copy's rows read, its connection back in the pool (pulled_visit
      // gives it back): the page is put together without it.
      const office_web::PulledVisit v = office_web::pulled_visit(
          cache_, db, req.get_param_value("tunnel"), req.get_param_value("visit"), photographs);
      db.release();
      office_web::test_gate("visit-assembly");
      storage::OpenOptions read;
      read.read_only = true;
      storage::ProjectStore store = storage::ProjectStore::open(v.file, read);
      body(s, db, store, v.visit_id, v.drive);
    });
  }

  // The server's uuid of a capture's photograph in a pulled copy.
  static std::string photograph_uuid(storage::ProjectStore& store, storage::RecordId capture,
                                     const std::string& side) {
    storage::sqlite::Connection db(store.file(), storage::sqlite::Connection::Access::read_only);
    storage::sqlite::Statement st(db,
                                  std::string("SELECT i.uuid FROM capture c JOIN image i ON i.id = "
                                              "c.") +
                                      (side == "left" ? "left" : "right") +
                                      "_image_id WHERE c.id = ?",
                                  "finding the photograph");
    st.bind(1, capture);
    if (!st.step() || st.column_text(0).empty())
      throw InputError("capture", "this visit has no such photograph");
    return st.column_text(0);
  }

  static fs::path exports_folder(OfficeSession& s, storage::ProjectStore& store,
                                 storage::RecordId id, const DriveFaces* drive) {
    // One export per pulled copy and visit: a new sync makes a new copy.
    const fs::path dir =
        s.folder / ("exports-" + store.file().stem().string() + "-" + std::to_string(id));
    if (!fs::exists(dir)) {
      const fs::path partial = fs::path(dir.string() + ".partial");
      fs::remove_all(partial);
      ExportRequest request;
      request.visit = id;
      request.out_dir = partial;
      request.drive = drive;
      export_visit(store, request);
      fs::rename(partial, dir);
    }
    return dir;
  }

  static std::string format_size(std::uintmax_t bytes) {
    if (bytes < 1024) return std::to_string(bytes) + " B";
    if (bytes < 1024 * 1024) return std::to_string((bytes + 512) / 1024) + " kB";
    return std::to_string((bytes + 512 * 1024) / (1024 * 1024)) + " MB";
  }

  static void asset(httplib::Response& res, const std::string& name) {
    const office_web::WebAsset* a = office_web::find_web_asset(name);
    if (!a) return send_error(res, 404, "no such page");
    res.set_content(std::string(a->bytes), std::string(a->content_type));
  }

  void three(httplib::Response& res, const std::string& relative) {
    // The route's pattern admits no "..": the file is inside three_folder.
    const fs::path file = options_.three_folder / relative;
    std::ifstream in(file, std::ios::binary);
    if (!in) return send_error(res, 404, "three.js is not installed (Debian: libjs-three)");
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    res.set_header("Cache-Control", "max-age=86400");
    res.set_content(std::move(bytes), "text/javascript; charset=utf-8");
  }

  OfficeServeOptions options_;
  bool tls_;
  // Before the sessions, which log in through it.
  office::ConnectionPool pool_;
  office_web::SessionStore sessions_;
  office_web::SharedOfficeCache cache_;
  // After the pool and the cache it uses: stopped before them.
  office_web::RoundsWorker rounds_;
  office_web::LoginThrottle throttle_;
  office_web::KnownBrowsers known_browsers_;
  std::unique_ptr<httplib::Server> http_;
  std::mutex sweep_lock_;
  std::chrono::steady_clock::time_point last_sweep_ = std::chrono::steady_clock::now();
};

}  // namespace

bool is_loopback_address(const std::string& host) {
  // An address as written, never a name that might resolve elsewhere
  // ("127.example.org" is a name): "localhost" is the one name taken.
  if (host == "localhost") return true;
  in_addr v4{};
  if (::inet_pton(AF_INET, host.c_str(), &v4) == 1) return (ntohl(v4.s_addr) >> 24) == 127;
  const std::string bare = host.size() > 2 && host.front() == '[' && host.back() == ']'
                               ? host.substr(1, host.size() - 2)
                               : host;
  in6_addr v6{};
  if (::inet_pton(AF_INET6, bare.c_str(), &v6) != 1) return false;
  if (IN6_IS_ADDR_LOOPBACK(&v6)) return true;
  // ::ffff:127.x.y.z, an IPv4 loopback address written as IPv6.
  return IN6_IS_ADDR_V4MAPPED(&v6) && v6.s6_addr[12] == 127;
}

void serve_office(const OfficeServeOptions& options,
                  const std::function<void(int port)>& on_listening) {
  if (options.tls_certificate.empty() != options.tls_key.empty())
    throw InputError("--tls", "give the certificate and its key: --tls CERT,KEY");
  if (options.tls_certificate.empty() && !is_loopback_address(options.listen_host))
    throw InputError("--listen",
                     "plain HTTP is served on a loopback address only (127.0.0.1, behind a "
                     "reverse proxy that speaks TLS); give --tls CERT,KEY to listen on " +
                         options.listen_host);
  OfficeServeOptions o = options;
  // A folder of this process's own inside the one given (or the system's
  // temporary folder): it is removed when the server stops.
  o.work_folder = (o.work_folder.empty() ? fs::temp_directory_path() : o.work_folder) /
                  ("rockface-office-" + std::to_string(::getpid()));
  fs::create_directories(o.work_folder);
  fs::permissions(o.work_folder, fs::perms::owner_all, fs::perm_options::replace);
  OfficeServer server(o);
  int port = o.listen_port;
  if (port == 0) {
    port = server.http().bind_to_any_port(o.listen_host);
    if (port <= 0) throw InputError("--listen", "cannot listen on " + o.listen_host);
  } else if (!server.http().bind_to_port(o.listen_host, port)) {
    throw InputError("--listen", "cannot listen on " + o.listen_host + ":" + std::to_string(port) +
                                     " (in use, or not this machine's)");
  }
  {
    std::lock_guard guard(running_lock);
    running = &server.http();
  }
  on_listening(port);
  server.http().listen_after_bind();
  {
    std::lock_guard guard(running_lock);
    running = nullptr;
  }
  std::error_code ec;
  fs::remove_all(o.work_folder, ec);
}

void stop_office_server() {
  std::lock_guard guard(running_lock);
  if (running) running->stop();
}

}  // namespace rockface::app
