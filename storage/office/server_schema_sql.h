#pragma once
// The SQL of each step of the office server's layout (server_schema.h).
// Kept apart from the code that runs it: these texts are the layout's
// history and never change once released.

namespace rockface::storage::office::sql {

// The group roles, created once per cluster (roles are not per database).
inline constexpr const char* kRoles = R"sql(
DO $$ BEGIN
  IF NOT EXISTS (SELECT 1 FROM pg_roles WHERE rolname = 'rockface_tablet') THEN
    CREATE ROLE rockface_tablet NOLOGIN;
  END IF;
  IF NOT EXISTS (SELECT 1 FROM pg_roles WHERE rolname = 'rockface_office') THEN
    CREATE ROLE rockface_office NOLOGIN;
  END IF;
  IF NOT EXISTS (SELECT 1 FROM pg_roles WHERE rolname = 'rockface_admin') THEN
    CREATE ROLE rockface_admin NOLOGIN CREATEROLE;
  END IF;
END $$;
)sql";

// Version 2's group role (issue 39): an office login that reads one tunnel
// (as the tunnel's member) and writes nothing. Roles belong to the cluster.
inline constexpr const char* kRolesVersion2 = R"sql(
DO $$ BEGIN
  IF NOT EXISTS (SELECT 1 FROM pg_roles WHERE rolname = 'rockface_tunnel_office') THEN
    CREATE ROLE rockface_tunnel_office NOLOGIN;
  END IF;
END $$;
)sql";

// The office web server's group (issue 46): a member of every office user,
// so that the web server's service role (a member of this group) may act
// as an office user (SET ROLE) on its pooled connections — and as no
// tablet or admin. The office users made before it are granted here; new
// ones by add_office_user. Roles belong to the cluster.
inline constexpr const char* kRolesWeb = R"sql(
DO $$ DECLARE r record; BEGIN
  IF NOT EXISTS (SELECT 1 FROM pg_roles WHERE rolname = 'rockface_web') THEN
    CREATE ROLE rockface_web NOLOGIN NOINHERIT;
  END IF;
  FOR r IN SELECT u.rolname FROM pg_roles u
           WHERE u.rolcanlogin AND u.rolname <> 'rockface_web'
             AND (pg_has_role(u.oid, 'rockface_office', 'MEMBER')
                  OR pg_has_role(u.oid, 'rockface_tunnel_office', 'MEMBER'))
             AND NOT pg_has_role(u.oid, 'rockface_admin', 'MEMBER')
             AND NOT pg_has_role(u.oid, 'rockface_tablet', 'MEMBER')
             -- the service roles themselves (members of office users
             -- through this group)
             AND NOT pg_has_role(u.oid, 'rockface_web', 'MEMBER')
             AND NOT pg_has_role('rockface_web', u.oid, 'MEMBER') LOOP
    EXECUTE format('GRANT %I TO rockface_web', r.rolname);
  END LOOP;
END $$;
)sql";

// Version 1. Records are append-only: a change on a tablet is a new revision
// (kind, uuid, revision), so the server keeps every record's history and a
// tablet never needs UPDATE or DELETE. A record's body is the tablet's row
// as JSON (storage/office/record_documents.h); its photographs and meshes
// are blobs referred to by SHA-256, and a record may only refer to a blob
// whose every byte arrived and was verified (record_blobs_complete).
inline constexpr const char* kVersion1 = R"sql(
CREATE SCHEMA rockface;
CREATE TABLE rockface.meta (key text PRIMARY KEY, value text NOT NULL);
CREATE TABLE rockface.tunnel (
  id bigserial PRIMARY KEY,
  name text NOT NULL UNIQUE CHECK (name <> ''),
  created_at timestamptz NOT NULL DEFAULT now(),
  created_by name NOT NULL DEFAULT current_user
);
CREATE TABLE rockface.tunnel_member (
  tunnel_id bigint NOT NULL REFERENCES rockface.tunnel(id) ON DELETE CASCADE,
  role_name name NOT NULL,
  PRIMARY KEY (tunnel_id, role_name)
);
CREATE TABLE rockface.project (
  uuid uuid PRIMARY KEY,
  tunnel_id bigint NOT NULL REFERENCES rockface.tunnel(id),
  owner name NOT NULL DEFAULT current_user,
  name text NOT NULL,
  first_synced_at timestamptz NOT NULL DEFAULT now()
);
CREATE TABLE rockface.visit (
  uuid uuid PRIMARY KEY,
  tunnel_id bigint NOT NULL REFERENCES rockface.tunnel(id),
  project_uuid uuid NOT NULL REFERENCES rockface.project(uuid),
  owner name NOT NULL DEFAULT current_user,
  local_id bigint NOT NULL,
  started_at text NOT NULL,
  synced_at timestamptz NOT NULL DEFAULT now()
);
CREATE INDEX visit_by_tunnel ON rockface.visit(tunnel_id, started_at);
CREATE TABLE rockface.blob (
  sha256 text PRIMARY KEY CHECK (sha256 ~ '^[0-9a-f]{64}$'),
  byte_size bigint NOT NULL CHECK (byte_size >= 0),
  chunk_size integer NOT NULL CHECK (chunk_size > 0),
  complete boolean NOT NULL DEFAULT false,
  created_by name NOT NULL DEFAULT current_user,
  created_at timestamptz NOT NULL DEFAULT now()
);
CREATE TABLE rockface.blob_chunk (
  sha256 text NOT NULL REFERENCES rockface.blob(sha256) ON DELETE CASCADE,
  idx integer NOT NULL CHECK (idx >= 0),
  bytes bytea NOT NULL,
  PRIMARY KEY (sha256, idx)
);
CREATE TABLE rockface.record (
  kind text NOT NULL,
  uuid uuid NOT NULL,
  revision integer NOT NULL CHECK (revision >= 1),
  tunnel_id bigint NOT NULL REFERENCES rockface.tunnel(id),
  project_uuid uuid NOT NULL REFERENCES rockface.project(uuid),
  visit_uuid uuid REFERENCES rockface.visit(uuid),
  local_id bigint,
  owner name NOT NULL DEFAULT current_user,
  project_schema integer NOT NULL,
  content_sha256 text NOT NULL,
  deleted boolean NOT NULL DEFAULT false,
  body jsonb,
  synced_at timestamptz NOT NULL DEFAULT now(),
  PRIMARY KEY (kind, uuid, revision)
);
CREATE INDEX record_by_tunnel_kind ON rockface.record(tunnel_id, kind, uuid, revision DESC);
CREATE INDEX record_by_visit ON rockface.record(visit_uuid);
CREATE TABLE rockface.sync_log (
  id bigserial PRIMARY KEY,
  project_uuid uuid NOT NULL,
  owner name NOT NULL DEFAULT current_user,
  started_at timestamptz NOT NULL,
  finished_at timestamptz NOT NULL DEFAULT now(),
  records integer NOT NULL, blobs integer NOT NULL, bytes bigint NOT NULL,
  client text NOT NULL
);
-- The latest revision of every record, with the reader's own rights.
CREATE VIEW rockface.record_current WITH (security_invoker = true) AS
  SELECT DISTINCT ON (kind, uuid) * FROM rockface.record ORDER BY kind, uuid, revision DESC;

CREATE FUNCTION rockface.is_admin() RETURNS boolean LANGUAGE sql STABLE AS
  $$ SELECT pg_has_role(current_user, 'rockface_admin', 'MEMBER') $$;
CREATE FUNCTION rockface.is_office() RETURNS boolean LANGUAGE sql STABLE AS
  $$ SELECT pg_has_role(current_user, 'rockface_office', 'MEMBER') OR rockface.is_admin() $$;
CREATE FUNCTION rockface.is_member(t bigint) RETURNS boolean LANGUAGE sql STABLE AS
  $$ SELECT EXISTS (SELECT 1 FROM rockface.tunnel_member m
                    WHERE m.tunnel_id = t AND pg_has_role(current_user, m.role_name, 'MEMBER')) $$;
-- Owners of rows the caller may not see (another tunnel's): definer's rights.
CREATE FUNCTION rockface.record_owner(k text, u uuid) RETURNS name LANGUAGE sql STABLE
  SECURITY DEFINER SET search_path = pg_catalog, rockface AS
  $$ SELECT owner FROM rockface.record WHERE kind = k AND uuid = u LIMIT 1 $$;
CREATE FUNCTION rockface.visit_owner(u uuid) RETURNS name LANGUAGE sql STABLE
  SECURITY DEFINER SET search_path = pg_catalog, rockface AS
  $$ SELECT owner FROM rockface.visit WHERE uuid = u $$;
CREATE FUNCTION rockface.project_owner(u uuid) RETURNS name LANGUAGE sql STABLE
  SECURITY DEFINER SET search_path = pg_catalog, rockface AS
  $$ SELECT owner FROM rockface.project WHERE uuid = u $$;
CREATE FUNCTION rockface.blob_is_complete(s text) RETURNS boolean LANGUAGE sql STABLE
  SECURITY DEFINER SET search_path = pg_catalog, rockface AS
  $$ SELECT coalesce((SELECT complete FROM rockface.blob WHERE sha256 = s), false) $$;

-- A blob is complete only when its chunks add up to its size and hash to
-- its name; a damaged upload loses its chunks and is sent again.
CREATE FUNCTION rockface.complete_blob(p_sha text) RETURNS boolean LANGUAGE plpgsql
  SECURITY DEFINER SET search_path = pg_catalog, rockface AS $$
DECLARE
  want bigint; done boolean; got_size bigint; got_sha text;
BEGIN
  SELECT byte_size, complete INTO want, done FROM rockface.blob WHERE sha256 = p_sha FOR UPDATE;
  IF NOT FOUND THEN
    RAISE EXCEPTION 'blob % is not on the server', p_sha USING ERRCODE = '23503';
  END IF;
  IF done THEN RETURN true; END IF;
  SELECT coalesce(sum(length(bytes)), 0),
         encode(sha256(coalesce(string_agg(bytes, ''::bytea ORDER BY idx), ''::bytea)), 'hex')
    INTO got_size, got_sha FROM rockface.blob_chunk WHERE sha256 = p_sha;
  IF got_size <> want OR got_sha <> p_sha THEN
    DELETE FROM rockface.blob_chunk WHERE sha256 = p_sha;
    RETURN false;
  END IF;
  UPDATE rockface.blob SET complete = true WHERE sha256 = p_sha;
  RETURN true;
END $$;

CREATE FUNCTION rockface.record_blobs_complete() RETURNS trigger LANGUAGE plpgsql
  SECURITY DEFINER SET search_path = pg_catalog, rockface AS $$
DECLARE
  missing text;
BEGIN
  SELECT q.s INTO missing
    FROM (SELECT jsonb_path_query(NEW.body, 'lax $.**."$blob"') #>> '{}' AS s) q
   WHERE NOT EXISTS (SELECT 1 FROM rockface.blob b WHERE b.sha256 = q.s AND b.complete)
   LIMIT 1;
  IF missing IS NOT NULL THEN
    RAISE EXCEPTION 'record % % refers to blob % that is not complete on the server',
      NEW.kind, NEW.uuid, missing USING ERRCODE = '23503';
  END IF;
  RETURN NEW;
END $$;
CREATE TRIGGER record_blobs_complete BEFORE INSERT ON rockface.record
  FOR EACH ROW EXECUTE FUNCTION rockface.record_blobs_complete();

ALTER TABLE rockface.tunnel ENABLE ROW LEVEL SECURITY;
ALTER TABLE rockface.project ENABLE ROW LEVEL SECURITY;
ALTER TABLE rockface.visit ENABLE ROW LEVEL SECURITY;
ALTER TABLE rockface.record ENABLE ROW LEVEL SECURITY;
ALTER TABLE rockface.blob ENABLE ROW LEVEL SECURITY;
ALTER TABLE rockface.blob_chunk ENABLE ROW LEVEL SECURITY;
ALTER TABLE rockface.sync_log ENABLE ROW LEVEL SECURITY;

CREATE POLICY admin_all ON rockface.tunnel USING (rockface.is_admin());
CREATE POLICY read_own_or_office ON rockface.tunnel FOR SELECT
  USING (rockface.is_office() OR rockface.is_member(id));

CREATE POLICY admin_all ON rockface.project USING (rockface.is_admin());
CREATE POLICY read_tunnel ON rockface.project FOR SELECT
  USING (rockface.is_office() OR rockface.is_member(tunnel_id));
CREATE POLICY tablet_adds ON rockface.project FOR INSERT
  WITH CHECK (owner = current_user AND rockface.is_member(tunnel_id));

CREATE POLICY admin_all ON rockface.visit USING (rockface.is_admin());
CREATE POLICY read_tunnel ON rockface.visit FOR SELECT
  USING (rockface.is_office() OR rockface.is_member(tunnel_id));
CREATE POLICY tablet_adds ON rockface.visit FOR INSERT
  WITH CHECK (owner = current_user AND rockface.is_member(tunnel_id)
              AND rockface.project_owner(project_uuid) = current_user);

CREATE POLICY admin_all ON rockface.record USING (rockface.is_admin());
CREATE POLICY read_tunnel ON rockface.record FOR SELECT
  USING (rockface.is_office() OR rockface.is_member(tunnel_id));
CREATE POLICY tablet_adds ON rockface.record FOR INSERT
  WITH CHECK (owner = current_user AND rockface.is_member(tunnel_id)
              AND rockface.project_owner(project_uuid) = current_user
              AND (visit_uuid IS NULL OR rockface.visit_owner(visit_uuid) = current_user)
              AND coalesce(rockface.record_owner(kind, uuid), current_user) = current_user);

CREATE POLICY admin_all ON rockface.blob USING (rockface.is_admin());
CREATE POLICY read_all ON rockface.blob FOR SELECT USING (true);
CREATE POLICY tablet_adds ON rockface.blob FOR INSERT
  WITH CHECK (created_by = current_user AND NOT complete);
CREATE POLICY admin_all ON rockface.blob_chunk USING (rockface.is_admin());
CREATE POLICY read_all ON rockface.blob_chunk FOR SELECT USING (true);
CREATE POLICY tablet_adds ON rockface.blob_chunk FOR INSERT
  WITH CHECK (NOT rockface.blob_is_complete(sha256));

CREATE POLICY admin_all ON rockface.sync_log USING (rockface.is_admin());
CREATE POLICY read_own_or_office ON rockface.sync_log FOR SELECT
  USING (rockface.is_office() OR owner = current_user);
CREATE POLICY tablet_adds ON rockface.sync_log FOR INSERT WITH CHECK (owner = current_user);

GRANT USAGE ON SCHEMA rockface TO rockface_tablet, rockface_office, rockface_admin;
GRANT SELECT ON ALL TABLES IN SCHEMA rockface TO rockface_tablet, rockface_office;
GRANT INSERT ON rockface.project, rockface.visit, rockface.record, rockface.blob,
  rockface.blob_chunk, rockface.sync_log TO rockface_tablet;
GRANT ALL ON ALL TABLES IN SCHEMA rockface TO rockface_admin;
GRANT USAGE ON ALL SEQUENCES IN SCHEMA rockface TO rockface_tablet, rockface_admin;
REVOKE EXECUTE ON FUNCTION rockface.complete_blob(text) FROM PUBLIC;
GRANT EXECUTE ON FUNCTION rockface.complete_blob(text) TO rockface_tablet, rockface_admin;
INSERT INTO rockface.meta (key, value) VALUES ('server_id', gen_random_uuid()::text);
)sql";

// Version 2 (issue 39): a photograph or a mesh is read only by those who may
// read a record referring to it. Version 1 let every role read every blob and
// chunk, so a tablet of one tunnel read another tunnel's photographs.
// - rockface.blob_ref says which tunnels' records refer to a blob; the record
//   trigger fills it (definer's rights) and its own row-level security is the
//   record's (office or a member of the tunnel).
// - A blob is readable when a readable blob_ref names it, or by its uploader
//   while the upload is unfinished (a resumed upload reads its own chunks); a
//   chunk is readable when its blob is, and added only by the blob's uploader.
// - rockface.blob_state tells a tablet whether a blob it may not read is
//   already on the server (its name is the hash of bytes the tablet holds, so
//   it learns nothing it does not already have): the same photograph synced
//   by two tunnels is stored once and not sent twice.
// - rockface_tunnel_office: an office login that reads one tunnel (as a
//   member) and writes nothing, besides rockface_office that reads them all.
inline constexpr const char* kVersion2 = R"sql(
CREATE TABLE rockface.blob_ref (
  sha256 text NOT NULL REFERENCES rockface.blob(sha256) ON DELETE CASCADE,
  tunnel_id bigint NOT NULL REFERENCES rockface.tunnel(id) ON DELETE CASCADE,
  PRIMARY KEY (sha256, tunnel_id)
);
CREATE INDEX blob_ref_by_tunnel ON rockface.blob_ref(tunnel_id);
INSERT INTO rockface.blob_ref (sha256, tunnel_id)
  SELECT DISTINCT q.s, r.tunnel_id
    FROM rockface.record r,
         LATERAL (SELECT jsonb_path_query(r.body, 'lax $.**."$blob"') #>> '{}' AS s) q
   WHERE EXISTS (SELECT 1 FROM rockface.blob b WHERE b.sha256 = q.s);

CREATE FUNCTION rockface.record_blob_refs() RETURNS trigger LANGUAGE plpgsql
  SECURITY DEFINER SET search_path = pg_catalog, rockface AS $$
BEGIN
  INSERT INTO rockface.blob_ref (sha256, tunnel_id)
    SELECT DISTINCT q.s, NEW.tunnel_id
      FROM (SELECT jsonb_path_query(NEW.body, 'lax $.**."$blob"') #>> '{}' AS s) q
    ON CONFLICT DO NOTHING;
  RETURN NULL;
END $$;
CREATE TRIGGER record_blob_refs AFTER INSERT ON rockface.record
  FOR EACH ROW EXECUTE FUNCTION rockface.record_blob_refs();

CREATE FUNCTION rockface.blob_uploader(s text) RETURNS name LANGUAGE sql STABLE
  SECURITY DEFINER SET search_path = pg_catalog, rockface AS
  $$ SELECT created_by FROM rockface.blob WHERE sha256 = s $$;
CREATE FUNCTION rockface.blob_state(s text)
  RETURNS TABLE (complete boolean, chunk_size integer, uploader name) LANGUAGE sql STABLE
  SECURITY DEFINER SET search_path = pg_catalog, rockface AS
  $$ SELECT complete, chunk_size, created_by FROM rockface.blob WHERE sha256 = s $$;

ALTER TABLE rockface.blob_ref ENABLE ROW LEVEL SECURITY;
CREATE POLICY admin_all ON rockface.blob_ref USING (rockface.is_admin());
CREATE POLICY read_tunnel ON rockface.blob_ref FOR SELECT
  USING (rockface.is_office() OR rockface.is_member(tunnel_id));

DROP POLICY read_all ON rockface.blob;
CREATE POLICY read_referred ON rockface.blob FOR SELECT
  USING ((created_by = current_user AND NOT complete)
         OR EXISTS (SELECT 1 FROM rockface.blob_ref r WHERE r.sha256 = blob.sha256));
DROP POLICY read_all ON rockface.blob_chunk;
CREATE POLICY read_with_blob ON rockface.blob_chunk FOR SELECT
  USING (EXISTS (SELECT 1 FROM rockface.blob b WHERE b.sha256 = blob_chunk.sha256));
DROP POLICY tablet_adds ON rockface.blob_chunk;
CREATE POLICY uploader_adds ON rockface.blob_chunk FOR INSERT
  WITH CHECK (rockface.blob_uploader(sha256) = current_user
              AND NOT rockface.blob_is_complete(sha256));

GRANT SELECT ON rockface.blob_ref TO rockface_tablet, rockface_office, rockface_tunnel_office;
GRANT ALL ON rockface.blob_ref TO rockface_admin;
GRANT USAGE ON SCHEMA rockface TO rockface_tunnel_office;
GRANT SELECT ON ALL TABLES IN SCHEMA rockface TO rockface_tunnel_office;
REVOKE EXECUTE ON FUNCTION rockface.blob_state(text) FROM PUBLIC;
GRANT EXECUTE ON FUNCTION rockface.blob_state(text) TO rockface_tablet, rockface_admin;
)sql";

// Version 3 (issue 46): the over- and underbreak of each round, kept. The
// office's rounds along a drive of 3,000 visits measured 3,000 meshes on
// every first request (753 s): each round's figures are now computed once
// and kept here with the inputs they were computed from (the latest
// revisions of the visit's and the tunnel's records, by content hash), so
// a request, a restarted web server or a second one reads them back, and a
// visit whose records changed is measured again. Derived figures only: no
// record changes. Readable by whoever may read the visit; written only
// through keep_round_figures, which only the office web server's group
// (rockface_web, acting as itself for that one statement) and admins may
// call — an office person's own role still writes nothing.
inline constexpr const char* kVersion3 = R"sql(
CREATE TABLE rockface.round_figures (
  visit_uuid uuid PRIMARY KEY REFERENCES rockface.visit(uuid) ON DELETE CASCADE,
  inputs text NOT NULL,
  figures jsonb NOT NULL,
  computed_at timestamptz NOT NULL DEFAULT now()
);
ALTER TABLE rockface.round_figures ENABLE ROW LEVEL SECURITY;
CREATE POLICY admin_all ON rockface.round_figures USING (rockface.is_admin());
CREATE POLICY read_visit ON rockface.round_figures FOR SELECT
  USING (EXISTS (SELECT 1 FROM rockface.visit v WHERE v.uuid = round_figures.visit_uuid));
CREATE FUNCTION rockface.keep_round_figures(v uuid, i text, f jsonb) RETURNS void
  LANGUAGE sql SECURITY DEFINER SET search_path = pg_catalog, rockface AS $$
  INSERT INTO rockface.round_figures (visit_uuid, inputs, figures) VALUES (v, i, f)
  ON CONFLICT (visit_uuid) DO UPDATE
    SET inputs = EXCLUDED.inputs, figures = EXCLUDED.figures, computed_at = now() $$;
REVOKE EXECUTE ON FUNCTION rockface.keep_round_figures(uuid, text, jsonb) FROM PUBLIC;
GRANT USAGE ON SCHEMA rockface TO rockface_web;
GRANT EXECUTE ON FUNCTION rockface.keep_round_figures(uuid, text, jsonb)
  TO rockface_web, rockface_admin;
GRANT SELECT ON rockface.round_figures TO rockface_office, rockface_tunnel_office;
GRANT ALL ON rockface.round_figures TO rockface_admin;
)sql";

}  // namespace rockface::storage::office::sql
