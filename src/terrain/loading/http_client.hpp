#pragma once
// HTTP GET for tile sources, on libcurl: timeouts, retries with exponential backoff, a limit on
// parallel requests across the process, conditional requests, and cancellation of a transfer in
// progress through a StopToken.
//
// Each thread keeps one curl easy handle in one multi handle, so a worker's connections to a
// server stay open from one tile to the next (keep-alive, one TLS handshake); DNS answers and
// TLS sessions are shared between threads. (libcurl does not support sharing a connection
// cache across threads.) A transfer runs in the thread's multi loop: a stop request wakes it
// at once (curl_multi_wakeup), the progress callback checks the token too.

#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "terrain/loading/stop_token.hpp"

namespace trailray::terrain {

// "trailray/<version> (+https://github.com/trailray/trailray)": tile servers ask that clients
// say who they are (the OpenStreetMap tile usage policy requires it).
std::string_view http_user_agent();

// A counting semaphore whose wait gives up when a stop_token is triggered.
class RequestLimiter {
 public:
  explicit RequestLimiter(int max_parallel);
  // One limiter shared by every source that is given none: 6 requests at a time, what browsers
  // open per host.
  static std::shared_ptr<RequestLimiter> process_wide();

  // Waits for a slot; false when `stop` was triggered first (no slot is then held).
  bool acquire(StopToken stop);
  void release();

  int max_parallel() const { return max_parallel_; }
  int in_use() const;

 private:
  const int max_parallel_;
  mutable std::mutex mutex_;
  std::condition_variable_any freed_;
  int in_use_ = 0;
};

struct RetryPolicy {
  int max_retries = 3;                         // after the first attempt
  std::chrono::milliseconds first_delay{250};  // then doubled each retry: 0.25 s, 0.5 s, 1 s
  std::chrono::milliseconds max_delay{8000};   // also caps a server's Retry-After
};

struct HttpClientOptions {
  std::chrono::milliseconds connect_timeout{10'000};
  std::chrono::milliseconds total_timeout{30'000};  // one attempt, connecting included
  RetryPolicy retry;
  // Sent with every request, e.g. {"Authorization", "Bearer ${TOKEN}"}: ${VAR} is expanded
  // from the environment at each request, and the values never appear in a message.
  std::vector<std::pair<std::string, std::string>> headers;
  std::shared_ptr<RequestLimiter> limiter;  // null: RequestLimiter::process_wide()
  std::size_t max_body_bytes = std::size_t{64} << 20;
};

struct HttpRequest {
  std::string url;                   // expanded: may hold secrets, so never put in a message
  std::vector<std::string> secrets;  // values to cut out of error messages
  std::string if_none_match;         // an ETag, for a conditional request
  std::string if_modified_since;     // a Last-Modified date, for a conditional request
};

struct CacheControl {
  std::optional<std::int64_t> max_age_s;
  bool no_store = false;  // must not be stored at all
  bool no_cache = false;  // may be stored, but must be revalidated before each use
};
CacheControl parse_cache_control(std::string_view header_value);

struct HttpResponse {
  int status = 0;  // the HTTP status of the last attempt; 0 when no response came (see error)
  std::vector<unsigned char> body;
  CacheControl cache_control;
  std::optional<std::int64_t> expires;  // Expires, Unix seconds (0 for an invalid date, "already expired")
  std::optional<std::int64_t> date;     // the server's Date, Unix seconds, to correct Expires for its clock
  std::string etag, last_modified, content_type;
  std::string error;  // what went wrong without a response (connection, timeout, ...), secrets cut out
  int retries = 0;    // attempts after the first
  bool cancelled = false;
  // No answer from the server: refused, unresolvable, reset, timed out (not a bad URL or an
  // oversized body). What a source treats as "the server is unreachable".
  bool network_error = false;

  bool transport_failed() const { return status == 0 && !cancelled; }
};

class HttpClient {
 public:
  explicit HttpClient(HttpClientOptions options = {});

  // Thread-safe. Retries connection errors, timeouts, 429 and 5xx (after backoff delays, during
  // which no slot of the limiter is held); a stop request ends the wait for a slot, a delay or
  // a transfer at once (cancelled = true).
  HttpResponse get(const HttpRequest& request, StopToken stop = {}) const;

  const HttpClientOptions& options() const { return options_; }

 private:
  HttpClientOptions options_;
};

}  // namespace trailray::terrain
