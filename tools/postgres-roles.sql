-- The roles of a training centre's session database on PostgreSQL (docs/SESSIONS.md, "Roles").
-- Run once as the database's owner, after the owner's first needle-sim run made the schema:
--   psql "postgresql://OWNER@HOST/needle" -f tools/postgres-roles.sql
-- then a login per station, named as the station (needle-sim run --station NAME, default the host
-- name), and per instructor:
--   CREATE ROLE "station-01" LOGIN PASSWORD '...' IN ROLE needle_station;
--   CREATE ROLE "dr-lee" LOGIN PASSWORD '...' IN ROLE needle_instructor;
-- A station inserts sessions as itself and reads and finishes only its own (row-level security on
-- every table of sessions); an instructor reads every session and writes nothing. The owner (who
-- migrates the schema) is not bound by the policies. Idempotent.
DO $$ BEGIN CREATE ROLE needle_station NOLOGIN; EXCEPTION WHEN duplicate_object THEN NULL; END $$;
DO $$ BEGIN CREATE ROLE needle_instructor NOLOGIN; EXCEPTION WHEN duplicate_object THEN NULL; END $$;

GRANT USAGE ON SCHEMA public TO needle_station, needle_instructor;
GRANT SELECT ON needle_schema, trainees, tasks, sessions, step_results, metrics, score_components, recording_chunks
  TO needle_station, needle_instructor;
GRANT INSERT ON trainees, tasks, sessions, step_results, metrics, score_components, recording_chunks TO needle_station;
GRANT UPDATE (name) ON trainees TO needle_station;           -- INSERT ... ON CONFLICT DO UPDATE
GRANT UPDATE (title, source) ON tasks TO needle_station;
GRANT UPDATE (status, ended_at, score, passed, duration_s) ON sessions TO needle_station;  -- finishing
GRANT USAGE ON ALL SEQUENCES IN SCHEMA public TO needle_station;

ALTER TABLE sessions ENABLE ROW LEVEL SECURITY;
DROP POLICY IF EXISTS station_own ON sessions;
CREATE POLICY station_own ON sessions TO needle_station
  USING (station = session_user) WITH CHECK (station = session_user);
DROP POLICY IF EXISTS instructor_reads ON sessions;
CREATE POLICY instructor_reads ON sessions FOR SELECT TO needle_instructor USING (true);

-- A session's rows follow the session: a station sees and adds them only for sessions it sees.
DO $$
DECLARE t text;
BEGIN
  FOREACH t IN ARRAY ARRAY['step_results', 'metrics', 'score_components', 'recording_chunks'] LOOP
    EXECUTE format('ALTER TABLE %I ENABLE ROW LEVEL SECURITY', t);
    EXECUTE format('DROP POLICY IF EXISTS station_own ON %I', t);
    EXECUTE format('CREATE POLICY station_own ON %I TO needle_station '
                   'USING (session_id IN (SELECT id FROM sessions)) WITH CHECK (session_id IN (SELECT id FROM sessions))', t);
    EXECUTE format('DROP POLICY IF EXISTS instructor_reads ON %I', t);
    EXECUTE format('CREATE POLICY instructor_reads ON %I FOR SELECT TO needle_instructor USING (true)', t);
  END LOOP;
END $$;
