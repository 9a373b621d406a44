// `rockface server init|add-tunnel|add-tablet|add-office|add-web|add-admin SERVER ...`: the
// site's PostgreSQL server set up by its administrator (schema, roles,
// row-level security; tunnels; tablet and office logins).
#include <iostream>
#include <memory>

#include "firmware-app/cli/verb_registry.h"
#include "firmware-app/office/office_workflows.h"

namespace rockface::app {
namespace {

struct ServerVerbOptions {
  std::string server, name, tunnel;
  std::string office_tunnel;  // add-office --tunnel: the one tunnel an office role reads
};

VerbRun setup_server(CLI::App& sub) {
  auto o = std::make_shared<ServerVerbOptions>();
  sub.require_subcommand(1);
  auto server_arg = [o](CLI::App* c) {
    c->add_option("SERVER", o->server,
                  "libpq connection string (postgresql://... or service=NAME) of a role that may "
                  "create roles")
        ->required();
  };
  CLI::App* init = sub.add_subcommand(
      "init", "create (or upgrade) the rockface schema, roles and row-level security policies");
  server_arg(init);
  CLI::App* tunnel = sub.add_subcommand("add-tunnel", "a tunnel that tablets add visits to");
  server_arg(tunnel);
  tunnel->add_option("NAME", o->name, "the tunnel's name")->required();
  CLI::App* tablet =
      sub.add_subcommand("add-tablet", "a tablet's login role, allowed to add visits to a tunnel");
  server_arg(tablet);
  tablet->add_option("ROLE", o->name, "the tablet's role name")->required();
  tablet->add_option("--tunnel", o->tunnel, "the tunnel it adds visits to")->required();
  CLI::App* office = sub.add_subcommand(
      "add-office", "an office login role that reads every tunnel, or one with --tunnel");
  server_arg(office);
  office->add_option("ROLE", o->name, "the role name")->required();
  office->add_option("--tunnel", o->office_tunnel, "the one tunnel it reads (default: all)");
  CLI::App* web = sub.add_subcommand(
      "add-web",
      "the login role `office serve` connects as: it acts as each office user, and as no other");
  server_arg(web);
  web->add_option("ROLE", o->name, "the role name")->required();
  CLI::App* admin = sub.add_subcommand(
      "add-admin",
      "a login role that creates tunnels, tablets and office users (needs a superuser)");
  server_arg(admin);
  admin->add_option("ROLE", o->name, "the role name")->required();
  return [o, init, tunnel, tablet, office, web, admin] {
    std::vector<std::string> lines;
    if (init->parsed()) lines = run_server_init(o->server);
    if (tunnel->parsed()) lines = run_server_add_tunnel(o->server, o->name);
    if (tablet->parsed()) lines = run_server_add_tablet(o->server, o->name, o->tunnel);
    if (office->parsed()) lines = run_server_add_office(o->server, o->name, o->office_tunnel);
    if (web->parsed()) lines = run_server_add_web(o->server, o->name);
    if (admin->parsed()) lines = run_server_add_admin(o->server, o->name);
    for (const auto& line : lines) std::cout << line << "\n";
    return 0;
  };
}

const VerbRegistrar server_verb{
    "server",
    "set up the site's PostgreSQL server: init (schema, roles, policies), add-tunnel, add-tablet, "
    "add-office, add-web, add-admin",
    setup_server};

}  // namespace
}  // namespace rockface::app
