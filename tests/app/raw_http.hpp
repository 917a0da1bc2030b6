#pragma once
// A raw HTTP/1.1 client on POSIX sockets for the serve tests: it sends any bytes (malformed,
// partial, oversized requests) and reads one response, so the tests see exactly what the server
// does with them.

#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cctype>
#include <chrono>
#include <map>
#include <optional>
#include <string>

namespace trailray::test::http_client {

// A connected socket to 127.0.0.1:port (closed at scope end), -1 inside when it failed.
class Socket {
 public:
  explicit Socket(int port) {
    fd_ = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
    sockaddr_in a{};
    a.sin_family = AF_INET;
    a.sin_port = htons(static_cast<std::uint16_t>(port));
    a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    if (fd_ >= 0 && ::connect(fd_, reinterpret_cast<sockaddr*>(&a), sizeof a) != 0) {
      ::close(fd_);
      fd_ = -1;
    }
  }
  ~Socket() {
    if (fd_ >= 0) ::close(fd_);
  }
  Socket(const Socket&) = delete;
  Socket& operator=(const Socket&) = delete;
  Socket(Socket&& o) noexcept : fd_(o.fd_) { o.fd_ = -1; }

  bool ok() const { return fd_ >= 0; }
  int fd() const { return fd_; }

  // Everything sent, unless the peer closed first (false).
  bool send_all(const std::string& bytes) {
    std::size_t done = 0;
    while (done < bytes.size()) {
      const ssize_t n = ::send(fd_, bytes.data() + done, bytes.size() - done, MSG_NOSIGNAL);
      if (n <= 0) return false;
      done += static_cast<std::size_t>(n);
    }
    return true;
  }

  // Whatever arrives within `timeout_s`, up to the peer's close or `limit` bytes, or until
  // `complete` says the bytes so far are a whole answer.
  template <class Complete>
  std::string receive(double timeout_s, Complete complete, std::size_t limit = 64u << 20) {
    std::string in;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
    char buf[65536];
    for (;;) {
      const auto left =
          std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
      if (left.count() <= 0) {
        timed_out_ = true;
        break;
      }
      pollfd p{fd_, POLLIN, 0};
      if (::poll(&p, 1, static_cast<int>(left.count())) <= 0) continue;
      const ssize_t n = ::recv(fd_, buf, sizeof buf, 0);
      if (n <= 0) {
        closed_ = true;
        break;
      }
      in.append(buf, static_cast<std::size_t>(n));
      if (complete(in) || in.size() >= limit) break;
    }
    return in;
  }
  bool timed_out() const { return timed_out_; }
  bool closed() const { return closed_; }

 private:
  int fd_ = -1;
  bool timed_out_ = false, closed_ = false;
};

struct Response {
  int status = 0;                              // 0: no answer (closed or timed out before a status line)
  std::map<std::string, std::string> headers;  // names in lower case
  std::string body;
  bool timed_out = false;
  double seconds = 0.0;  // from the request's first byte to the whole answer

  std::string header(const std::string& name) const {
    auto it = headers.find(name);
    return it == headers.end() ? std::string() : it->second;
  }
};

inline std::optional<std::size_t> content_length(const std::string& head) {
  std::string lower;
  for (char c : head) lower += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  const std::size_t at = lower.find("\r\ncontent-length:");
  if (at == std::string::npos) return std::nullopt;
  return std::stoul(lower.substr(at + 17));
}

// One answer from what a socket receives (`head_only`: HEAD, no body follows).
inline Response read_response(Socket& s, double timeout_s, bool head_only = false) {
  const auto start = std::chrono::steady_clock::now();
  const std::string raw = s.receive(timeout_s, [head_only](const std::string& in) {
    const std::size_t end = in.find("\r\n\r\n");
    if (end == std::string::npos) return false;
    if (head_only) return true;
    const auto length = content_length(in.substr(0, end + 2));
    return length && in.size() >= end + 4 + *length;
  });
  Response r;
  r.timed_out = s.timed_out();
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const std::size_t end = raw.find("\r\n\r\n");
  if (!raw.starts_with("HTTP/1.") || raw.size() < 12) return r;
  r.status = std::stoi(raw.substr(9, 3));
  std::size_t line = raw.find("\r\n") + 2;
  while (end != std::string::npos && line < end) {
    const std::size_t next = raw.find("\r\n", line);
    const std::string h = raw.substr(line, next - line);
    const std::size_t colon = h.find(':');
    if (colon != std::string::npos) {
      std::string name = h.substr(0, colon);
      for (char& c : name) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
      std::string value = h.substr(colon + 1);
      while (!value.empty() && value.front() == ' ') value.erase(0, 1);
      r.headers[name] = value;
    }
    line = next + 2;
  }
  if (end != std::string::npos) r.body = raw.substr(end + 4);
  return r;
}

// One request as raw bytes on a new connection, and its answer.
inline Response exchange(int port, const std::string& request, double timeout_s = 30.0, bool head_only = false) {
  Socket s(port);
  if (!s.ok()) return {};
  s.send_all(request);
  return read_response(s, timeout_s, head_only);
}

inline Response get(int port, const std::string& target, const std::string& method = "GET") {
  return exchange(port, method + " " + target + " HTTP/1.1\r\nHost: 127.0.0.1\r\nConnection: close\r\n\r\n", 30.0,
                  method == "HEAD");
}

}  // namespace trailray::test::http_client
