#pragma once
// A small RAII layer over the SQLite C API: a connection, prepared statements with typed
// binds and column reads, and a transaction guard that rolls back unless committed.
// Every failure throws SqliteError with SQLite's message; nothing here hides an error code.
#include <cstdint>
#include <filesystem>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

struct sqlite3;
struct sqlite3_stmt;

namespace esc::store::sql {

class SqliteError : public std::runtime_error {
 public:
  SqliteError(int code, const std::string& what) : std::runtime_error(what), code_(code) {}
  [[nodiscard]] int code() const noexcept { return code_; }

 private:
  int code_;
};

class Statement;

class Database {
 public:
  enum class Mode { Create, ReadWrite, ReadOnly };
  // Create: the file must not exist yet. ReadWrite and ReadOnly: it must exist.
  Database(const std::filesystem::path& file, Mode mode);
  ~Database();
  Database(const Database&) = delete;
  Database& operator=(const Database&) = delete;
  Database(Database&& other) noexcept;
  Database& operator=(Database&& other) noexcept;

  // Runs one or more statements without results.
  void exec(std::string_view sql);
  [[nodiscard]] Statement prepare(std::string_view sql);
  // Whether the database has a table of that name (an older schema may lack one, or still
  // hold one a later schema dropped).
  [[nodiscard]] bool has_table(std::string_view name);
  [[nodiscard]] std::int64_t last_insert_rowid() const noexcept;
  [[nodiscard]] sqlite3* handle() const noexcept { return db_; }

 private:
  [[noreturn]] void fail(int code, std::string_view context) const;
  sqlite3* db_ = nullptr;
  friend class Statement;
};

class Statement {
 public:
  Statement(Database& db, std::string_view sql);
  ~Statement();
  Statement(const Statement&) = delete;
  Statement& operator=(const Statement&) = delete;
  Statement(Statement&& other) noexcept;
  Statement& operator=(Statement&&) = delete;

  // Binds by 1-based index; returns *this to chain.
  Statement& bind(int index, std::int64_t value);
  Statement& bind(int index, int value) { return bind(index, static_cast<std::int64_t>(value)); }
  Statement& bind(int index, double value);
  Statement& bind(int index, std::string_view text);
  Statement& bind(int index, const char* text) { return bind(index, std::string_view(text)); }
  Statement& bind(int index, const std::string& text) { return bind(index, std::string_view(text)); }
  Statement& bind_blob(int index, std::span<const double> values);
  Statement& bind_blob(int index, std::span<const std::uint8_t> bytes);
  Statement& bind_null(int index);

  // Advances to the next row: true while there is one. Throws on error.
  bool step();
  // Runs a statement without results to completion and resets it for reuse.
  void run();
  void reset();

  [[nodiscard]] bool is_null(int column) const;
  [[nodiscard]] std::int64_t int64(int column) const;
  [[nodiscard]] int integer(int column) const { return static_cast<int>(int64(column)); }
  [[nodiscard]] double real(int column) const;
  [[nodiscard]] std::string text(int column) const;
  // A blob of native doubles (see bind_blob); throws if its size is not a multiple of 8.
  [[nodiscard]] std::vector<double> doubles(int column) const;

  // The row as SQLite holds it, column by column, whatever the column (row_checksum.cpp).
  enum class Type { Integer, Real, Text, Blob, Null };
  [[nodiscard]] int column_count() const;
  [[nodiscard]] std::string column_name(int column) const;
  [[nodiscard]] Type type(int column) const;
  // The bytes of a text or blob column.
  [[nodiscard]] std::string_view bytes(int column) const;

 private:
  Database* db_;
  sqlite3_stmt* stmt_ = nullptr;
};

// BEGIN IMMEDIATE ... COMMIT; rolls back in the destructor unless commit() was called.
class Transaction {
 public:
  explicit Transaction(Database& db);
  ~Transaction();
  Transaction(const Transaction&) = delete;
  Transaction& operator=(const Transaction&) = delete;
  void commit();

 private:
  Database* db_;
  bool done_ = false;
};

}  // namespace esc::store::sql
