#pragma once
// The results database's SQLite, as owned objects: a connection, prepared statements and
// transactions. Every failure is an aco::Error naming the file and SQLite's reason. Values bind
// and read as trial fields' cells (TrialCell), so that the tables' columns hold them unchanged.
#include <sqlite3.h>

#include <bit>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "aco/parameters.hpp"
#include "aco/studies/trial_record.hpp"

namespace aco::studies::sqlite {

// 64-bit unsigned values keep their bits in SQLite's signed integers.
inline std::int64_t to_sql(std::uint64_t v) { return std::bit_cast<std::int64_t>(v); }
inline std::uint64_t from_sql(std::int64_t v) { return std::bit_cast<std::uint64_t>(v); }

// A real that binds as SQL NULL.
inline constexpr double kNull = std::numeric_limits<double>::quiet_NaN();

// How a connection opens its file.
enum class Access {
  write,  // reading and writing; a missing file is created
  read,  // reading only: the file may be on a read-only file system or not ours to write
  // reading only a file nothing writes (no -shm file beside a WAL database, on a read-only file
  // system: SQLite cannot make one, and no writer could be using it)
  read_unchanging,
};

// One connection.
class Connection {
 public:
  explicit Connection(const std::filesystem::path& file, Access access = Access::write);
  ~Connection() { sqlite3_close(db_); }
  Connection(const Connection&) = delete;
  Connection& operator=(const Connection&) = delete;

  // An Error unless `rc` is a success; `doing` says what failed.
  void check(int rc, const std::string& doing) const;
  void exec(const std::string& sql) { check(sqlite3_exec(db_, sql.c_str(), nullptr, nullptr, nullptr), sql); }

  sqlite3* handle() const { return db_; }
  const std::string& file() const { return file_; }

 private:
  std::string file_;
  sqlite3* db_ = nullptr;
};

// A prepared statement, reset before each use so it can be kept and reused.
class Statement {
 public:
  Statement(const Connection& db, std::string sql);
  ~Statement() { sqlite3_finalize(stmt_); }
  Statement(const Statement&) = delete;
  Statement& operator=(const Statement&) = delete;

  // Starts a new execution with these parameters (?1, ?2, ...).
  template <class... Values>
  Statement& run(const Values&... values) {
    sqlite3_reset(stmt_);
    db_.check(sqlite3_clear_bindings(stmt_), sql_);
    int index = 0;
    (bind(++index, values), ...);
    return *this;
  }
  // The next row: true if there is one, false when done.
  bool next() {
    const int rc = sqlite3_step(stmt_);
    db_.check(rc, sql_);
    return rc == SQLITE_ROW;
  }
  // Binds `cells` to the parameters from `first` on, after those run() bound.
  Statement& and_cells(int first, const std::vector<TrialCell>& cells) {
    for (const auto& cell : cells) bind(first++, cell);
    return *this;
  }
  void finish() {
    while (next()) {}
  }
  // Whether the statement yields a row; reset at once so it holds no read open.
  bool any() {
    const bool found = next();
    sqlite3_reset(stmt_);
    return found;
  }

  bool null(int column) const { return sqlite3_column_type(stmt_, column) == SQLITE_NULL; }
  int type(int column) const { return sqlite3_column_type(stmt_, column); }  // SQLITE_INTEGER...
  // The stored value as a message shows it: "NULL", "the text 'abc'", "a blob of 2 bytes", "-5".
  std::string shown(int column) const;
  // A value of a column without a declared type, as SQLite stored it.
  aco::ParamValue value(int column) const;
  // A column holding a trial field of `type`.
  TrialCell cell(int column, TrialCellType type) const;
  std::int64_t integer(int column) const { return sqlite3_column_int64(stmt_, column); }
  double real(int column) const { return sqlite3_column_double(stmt_, column); }
  std::string text(int column) const;

  const std::string& file() const { return db_.file(); }

 private:
  void bind(int i, std::int64_t v) { db_.check(sqlite3_bind_int64(stmt_, i, v), sql_); }
  void bind(int i, int v) { bind(i, static_cast<std::int64_t>(v)); }
  void bind(int i, bool v) { bind(i, static_cast<std::int64_t>(v)); }
  void bind(int i, double v);  // NaN: NULL
  void bind(int i, const std::string& v) {
    db_.check(sqlite3_bind_text(stmt_, i, v.data(), static_cast<int>(v.size()), SQLITE_TRANSIENT), sql_);
  }
  void bind(int i, std::uint64_t v) { bind(i, to_sql(v)); }
  void bind(int i, std::monostate) { db_.check(sqlite3_bind_null(stmt_, i), sql_); }
  void bind(int i, const TrialCell& v) {
    std::visit([&](const auto& value) { bind(i, value); }, v);
  }
  template <class T>
  void bind(int i, const std::optional<T>& v) {
    if (v)
      bind(i, *v);
    else
      db_.check(sqlite3_bind_null(stmt_, i), sql_);
  }

  const Connection& db_;
  std::string sql_;
  sqlite3_stmt* stmt_ = nullptr;
};

// BEGIN IMMEDIATE takes the write lock at once, so a check and the write it guards are atomic
// even against another process. Rolled back unless committed.
class Transaction {
 public:
  explicit Transaction(Connection& db) : db_(db) { db_.exec("BEGIN IMMEDIATE"); }
  ~Transaction();
  Transaction(const Transaction&) = delete;
  Transaction& operator=(const Transaction&) = delete;
  void commit() {
    db_.exec("COMMIT");
    committed_ = true;
  }

 private:
  Connection& db_;
  bool committed_ = false;
};

}  // namespace aco::studies::sqlite
