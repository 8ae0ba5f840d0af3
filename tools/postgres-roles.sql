-- The roles of a training centre's session database on PostgreSQL (docs/SESSIONS.md, "Roles").
-- Run once by the database's owner, after the owner's first needle-sim run made the schema:
--   psql -v ON_ERROR_STOP=1 "postgresql://OWNER@HOST/needle" -f tools/postgres-roles.sql
-- then a login per station, named as the station (needle-sim run --station NAME, default the host
-- name), and per instructor:
--   CREATE ROLE "station-01" LOGIN PASSWORD '...' IN ROLE needle_station;
--   CREATE ROLE "dr-lee" LOGIN PASSWORD '...' IN ROLE needle_instructor;
--
-- It needs the owner of the session tables (schema version 4 or later) with CREATEROLE, or a
-- superuser: it checks that first and stops, saying what is missing. It runs in one transaction:
-- whole or not at all. Run again, it leaves the same grants and policies (what an earlier version
-- granted is revoked first).
--
-- What each role may do, and no more:
--   needle_station    reads the trainees, the tasks and the schema version; inserts trainees and
--                     tasks, never changes or deletes one; inserts sessions in its own name only
--                     (sessions.station = its login role), incomplete; sees only its own sessions
--                     and their rows; appends steps, metrics, the score breakdown and the
--                     recording to its own incomplete sessions; finishes them (status, end time,
--                     score, passed, duration). Nothing of a complete session can change (the
--                     schema's triggers refuse it, for every role); it deletes nothing.
--   needle_instructor reads every session, its rows, its checks and the trainees' renames; keeps
--                     checks of sessions in its own name (needle-sim verify); corrects a trainee's
--                     name (needle-sim trainee rename: the store logs it, who and when); changes
--                     nothing else.
--   the owner         migrates the schema; not bound by the policies (the triggers hold it too).
BEGIN;

DO $$
DECLARE
  me pg_roles%ROWTYPE;
  owner name;
  missing text[] := '{}';
BEGIN
  SELECT * INTO me FROM pg_roles WHERE rolname = current_user;
  IF NOT (me.rolcreaterole OR me.rolsuper) THEN
    missing := missing || format('the CREATEROLE attribute (role %I has neither it nor SUPERUSER; '
                                 'ALTER ROLE %I CREATEROLE, as an administrator)', current_user, current_user);
  END IF;
  IF to_regclass('public.needle_schema') IS NULL OR to_regclass('public.sessions') IS NULL THEN
    missing := missing || 'the session schema (the owner''s first needle-sim run makes it)'::text;
  ELSE
    SELECT pg_get_userbyid(relowner) INTO owner FROM pg_class WHERE oid = 'public.sessions'::regclass;
    IF owner <> current_user AND NOT me.rolsuper THEN
      missing := missing || format('ownership of the session tables (they belong to %I, not %I)', owner, current_user);
    ELSIF (SELECT max(version) FROM public.needle_schema) < 4 THEN
      missing := missing || format('schema version 4 (the database has %s: the owner''s next needle-sim run migrates it)',
                                   (SELECT max(version) FROM public.needle_schema));
    END IF;
  END IF;
  IF cardinality(missing) > 0 THEN
    RAISE EXCEPTION 'tools/postgres-roles.sql: nothing was changed: missing %', array_to_string(missing, '; and ');
  END IF;
END $$;

DO $$ BEGIN CREATE ROLE needle_station NOLOGIN; EXCEPTION WHEN duplicate_object THEN NULL; END $$;
DO $$ BEGIN CREATE ROLE needle_instructor NOLOGIN; EXCEPTION WHEN duplicate_object THEN NULL; END $$;

-- From nothing: table, column and sequence rights of an earlier version go first.
REVOKE ALL ON ALL TABLES IN SCHEMA public FROM needle_station, needle_instructor;
REVOKE ALL ON ALL SEQUENCES IN SCHEMA public FROM needle_station, needle_instructor;

GRANT USAGE ON SCHEMA public TO needle_station, needle_instructor;
GRANT SELECT ON needle_schema, trainees, tasks, sessions, step_results, metrics, score_components, recording_chunks,
  session_checks TO needle_station, needle_instructor;
GRANT INSERT ON trainees, tasks, sessions, step_results, metrics, score_components, recording_chunks TO needle_station;
GRANT UPDATE (status, ended_at, score, passed, duration_s) ON sessions TO needle_station;  -- finishing
GRANT USAGE ON SEQUENCE trainees_id_seq, tasks_id_seq, sessions_id_seq TO needle_station;
GRANT SELECT ON trainee_renames TO needle_instructor;
GRANT UPDATE (name) ON trainees TO needle_instructor;  -- needle-sim trainee rename, logged by the schema
GRANT INSERT ON session_checks TO needle_instructor;   -- needle-sim verify
GRANT USAGE ON SEQUENCE session_checks_id_seq TO needle_instructor;

-- Row-level security: the policies below are all there is (earlier ones dropped).
DO $$
DECLARE
  t text;
  p record;
BEGIN
  FOREACH t IN ARRAY ARRAY['sessions', 'step_results', 'metrics', 'score_components', 'recording_chunks', 'session_checks'] LOOP
    EXECUTE format('ALTER TABLE %I ENABLE ROW LEVEL SECURITY', t);
    FOR p IN SELECT policyname FROM pg_policies WHERE schemaname = 'public' AND tablename = t LOOP
      EXECUTE format('DROP POLICY %I ON %I', p.policyname, t);
    END LOOP;
    EXECUTE format('CREATE POLICY instructor_reads ON %I FOR SELECT TO needle_instructor USING (true)', t);
  END LOOP;
  -- A session's rows follow the session: a station sees them for the sessions it sees, and adds
  -- them to its incomplete ones.
  FOREACH t IN ARRAY ARRAY['step_results', 'metrics', 'score_components', 'recording_chunks'] LOOP
    EXECUTE format('CREATE POLICY station_reads ON %I FOR SELECT TO needle_station '
                   'USING (session_id IN (SELECT id FROM sessions))', t);
    EXECUTE format('CREATE POLICY station_appends ON %I FOR INSERT TO needle_station '
                   'WITH CHECK (session_id IN (SELECT id FROM sessions WHERE status = ''incomplete''))', t);
  END LOOP;
END $$;
CREATE POLICY station_reads ON sessions FOR SELECT TO needle_station USING (station = session_user);
CREATE POLICY station_begins ON sessions FOR INSERT TO needle_station
  WITH CHECK (station = session_user AND status = 'incomplete');
-- Its own sessions, whatever their status: an update of a complete one then meets the schema's
-- trigger, which refuses it with an error rather than changing nothing in silence.
CREATE POLICY station_finishes ON sessions FOR UPDATE TO needle_station
  USING (station = session_user) WITH CHECK (station = session_user);
CREATE POLICY station_reads ON session_checks FOR SELECT TO needle_station USING (session_id IN (SELECT id FROM sessions));
CREATE POLICY instructor_checks ON session_checks FOR INSERT TO needle_instructor WITH CHECK (checked_by = session_user);

COMMIT;
