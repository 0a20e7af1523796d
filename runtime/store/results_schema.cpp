#include "runtime/store/results_schema.hpp"

namespace esc::store {

namespace {

// Every table but meta ends its columns with `checksum` (schema 5, row_checksum.hpp): the
// hash of the row's other columns, written with the row.
constexpr const char* kSchema = R"sql(
CREATE TABLE meta (
  key   TEXT PRIMARY KEY,
  value TEXT NOT NULL
);
CREATE TABLE experiments (
  id               INTEGER PRIMARY KEY,
  name             TEXT NOT NULL,
  seed             TEXT NOT NULL,
  content_hash     TEXT NOT NULL,
  status           TEXT NOT NULL CHECK (status IN ('running', 'finished')),
  created          TEXT NOT NULL,
  software_version TEXT NOT NULL,
  script_path      TEXT NOT NULL,
  overrides        TEXT NOT NULL,
  arena            TEXT NOT NULL,
  robot_radius_m   REAL NOT NULL,
  runs             INTEGER NOT NULL,
  generations      INTEGER NOT NULL,
  epochs           INTEGER NOT NULL,
  steps            INTEGER NOT NULL,
  checksum         INTEGER NOT NULL DEFAULT 0
);
CREATE TABLE sources (
  experiment_id INTEGER NOT NULL REFERENCES experiments(id),
  idx           INTEGER NOT NULL,
  name          TEXT NOT NULL,
  text          TEXT NOT NULL,
  checksum      INTEGER NOT NULL DEFAULT 0,
  PRIMARY KEY (experiment_id, idx)
);
CREATE TABLE settings (
  experiment_id INTEGER NOT NULL REFERENCES experiments(id),
  key           TEXT NOT NULL,
  value         TEXT NOT NULL,
  checksum      INTEGER NOT NULL DEFAULT 0,
  PRIMARY KEY (experiment_id, key)
);
CREATE TABLE controllers (
  id            INTEGER PRIMARY KEY,
  experiment_id INTEGER NOT NULL REFERENCES experiments(id),
  idx           INTEGER NOT NULL,
  name          TEXT NOT NULL,
  architecture  TEXT NOT NULL,
  genome_size   INTEGER NOT NULL,
  head          TEXT NOT NULL,
  actions       TEXT NOT NULL,
  algorithm     TEXT,              -- schema 7; NULL in older rows: `gp` for a tree, else `es`
  checksum      INTEGER NOT NULL DEFAULT 0,
  UNIQUE (experiment_id, name)
);
CREATE TABLE runs (
  controller_id    INTEGER NOT NULL REFERENCES controllers(id),
  run              INTEGER NOT NULL,
  seed             TEXT NOT NULL,
  status           TEXT NOT NULL CHECK (status IN ('running', 'finished')),
  generations_done INTEGER NOT NULL,
  best_fitness     REAL,
  best_generation  INTEGER,
  best_index       INTEGER,
  best_genome      BLOB,
  best_tree        TEXT,
  best_behavior    TEXT,
  stopped          TEXT,             -- schema 7: why the optimizer ended the search early
  -- 8: the run's evaluations up to its first success (`success when`); NULL: none yet
  success_evaluation INTEGER,
  checksum         INTEGER NOT NULL DEFAULT 0,
  PRIMARY KEY (controller_id, run)
);
CREATE TABLE generations (
  controller_id INTEGER NOT NULL REFERENCES controllers(id),
  run           INTEGER NOT NULL,
  generation    INTEGER NOT NULL,
  best          REAL NOT NULL,
  mean          REAL NOT NULL,
  sd            REAL NOT NULL,
  evaluations   INTEGER NOT NULL,
  steps         INTEGER NOT NULL,
  seconds       REAL NOT NULL,
  -- Evaluations whose fitness saturated at +-1e300 (schema 5: an older database gets the
  -- column, 0, when opened for writing and reads as 0 otherwise).
  saturated     INTEGER NOT NULL DEFAULT 0,
  -- Schema 9: the optimizer's metrics (metric_tables.hpp), NULL when it reports none: the
  -- indexes of their names in metric_names ("0,1,2") and their values, doubles.
  metric_names  TEXT,
  metrics       BLOB,
  checksum      INTEGER NOT NULL DEFAULT 0,
  PRIMARY KEY (controller_id, run, generation)
);
CREATE TABLE run_state (
  controller_id INTEGER NOT NULL REFERENCES controllers(id),
  run           INTEGER NOT NULL,
  parents       INTEGER NOT NULL,
  genome_size   INTEGER NOT NULL,
  sigma_count   INTEGER NOT NULL,
  population    BLOB NOT NULL,
  checksum      INTEGER NOT NULL DEFAULT 0,
  PRIMARY KEY (controller_id, run)
);
-- Schema 2 (GP); also what opening a schema-1 database for writing adds to it.
CREATE TABLE tree_state (
  controller_id INTEGER NOT NULL REFERENCES controllers(id),
  run           INTEGER NOT NULL,
  individuals   INTEGER NOT NULL,
  population    BLOB NOT NULL,
  checksum      INTEGER NOT NULL DEFAULT 0,
  PRIMARY KEY (controller_id, run)
);
CREATE TABLE behavior_usage (
  controller_id INTEGER NOT NULL REFERENCES controllers(id),
  run           INTEGER NOT NULL,
  action_idx    INTEGER NOT NULL,
  action        TEXT NOT NULL,
  steps         INTEGER NOT NULL,
  checksum      INTEGER NOT NULL DEFAULT 0,
  PRIMARY KEY (controller_id, run, action_idx)
);
CREATE TABLE replays (
  controller_id INTEGER PRIMARY KEY REFERENCES controllers(id),
  run           INTEGER NOT NULL,
  seed          TEXT NOT NULL,
  fitness       REAL NOT NULL,
  columns       TEXT NOT NULL,
  trace         BLOB NOT NULL,
  checksum      INTEGER NOT NULL DEFAULT 0
);
-- Schema 6: every optimizer's state (optimizer_tables.hpp); run_state and tree_state above
-- are read only, for runs an older esc left.
CREATE TABLE optimizer_state (
  controller_id INTEGER NOT NULL REFERENCES controllers(id),
  run           INTEGER NOT NULL,
  algorithm     TEXT NOT NULL,
  format        INTEGER NOT NULL,
  state         BLOB NOT NULL,
  -- Schema 9: NULL while the run goes on (`state` the bytes as saved); a finished run's are
  -- zlib-compressed, this many bytes once uncompressed (NEAT's 300 KB become about 40).
  raw_size      INTEGER,
  checksum      INTEGER NOT NULL DEFAULT 0,
  PRIMARY KEY (controller_id, run)
);
-- Schema 3 (studies); also what opening an older database for writing adds to it.
CREATE TABLE studies (
  id            INTEGER PRIMARY KEY,
  name          TEXT NOT NULL,
  seed          TEXT NOT NULL,
  checksum      INTEGER NOT NULL DEFAULT 0
);
CREATE TABLE conditions (
  experiment_id INTEGER PRIMARY KEY REFERENCES experiments(id),
  study_id      INTEGER NOT NULL REFERENCES studies(id),
  idx           INTEGER NOT NULL,
  name          TEXT NOT NULL,
  directory     TEXT NOT NULL,
  sweep         INTEGER,
  checksum      INTEGER NOT NULL DEFAULT 0,
  UNIQUE (study_id, name)
);
CREATE TABLE condition_settings (
  experiment_id INTEGER NOT NULL REFERENCES conditions(experiment_id),
  idx           INTEGER NOT NULL,
  key           TEXT NOT NULL,
  value         TEXT NOT NULL,
  swept         INTEGER NOT NULL,
  x             REAL,
  x_unit        TEXT NOT NULL,
  checksum      INTEGER NOT NULL DEFAULT 0,
  PRIMARY KEY (experiment_id, idx)
);
)sql";

}  // namespace

const char* results_schema() { return kSchema; }

}  // namespace esc::store
