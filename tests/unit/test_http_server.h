// A small HTTP/1.1 server on 127.0.0.1 for cache tests, behaving like
// bazel-remote for what facet uses: GET and PUT under /ac/ and /cas/, and a
// PUT to /cas/<sha256> whose body does not hash to its name is refused.
#pragma once

#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <atomic>
#include <functional>
#include <map>
#include <mutex>
#include <string>
#include <thread>

namespace facet::test_http {

class TestHttpServer {
 public:
  // `sha256`: the digest function the server checks /cas/ bodies with.
  explicit TestHttpServer(std::function<std::string(std::string_view)> sha256) : sha256_(std::move(sha256)) {
    fd_ = ::socket(AF_INET, SOCK_STREAM, 0);
    int one = 1;
    ::setsockopt(fd_, SOL_SOCKET, SO_REUSEADDR, &one, sizeof one);
    sockaddr_in addr{};
    addr.sin_family = AF_INET;
    addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    addr.sin_port = 0;
    ::bind(fd_, reinterpret_cast<sockaddr*>(&addr), sizeof addr);
    socklen_t len = sizeof addr;
    ::getsockname(fd_, reinterpret_cast<sockaddr*>(&addr), &len);
    port_ = ntohs(addr.sin_port);
    ::listen(fd_, 64);
    thread_ = std::thread([this] { serve(); });
  }
  ~TestHttpServer() {
    stop_ = true;
    thread_.join();
    ::close(fd_);
  }

  std::string url() const { return "http://127.0.0.1:" + std::to_string(port_); }
  int gets() const { return gets_; }
  int puts() const { return puts_; }
  std::map<std::string, std::string> objects() {
    std::lock_guard lock(mutex_);
    return objects_;
  }
  void set(const std::string& path, std::string body) {
    std::lock_guard lock(mutex_);
    objects_[path] = std::move(body);
  }

 private:
  void serve() {
    while (!stop_) {
      pollfd p{fd_, POLLIN, 0};
      if (::poll(&p, 1, 50) <= 0) continue;
      int client = ::accept(fd_, nullptr, nullptr);
      if (client >= 0) handle(client);
    }
  }

  static bool read_more(int fd, std::string& buffer) {
    char chunk[65536];
    ssize_t n = ::recv(fd, chunk, sizeof chunk, 0);
    if (n <= 0) return false;
    buffer.append(chunk, size_t(n));
    return true;
  }

  static void send_all(int fd, const std::string& s) {
    size_t sent = 0;
    while (sent < s.size()) {
      ssize_t n = ::send(fd, s.data() + sent, s.size() - sent, MSG_NOSIGNAL);
      if (n <= 0) return;
      sent += size_t(n);
    }
  }

  static void respond(int fd, int status, const std::string& body) {
    const char* reason = status == 200 ? "OK" : status == 404 ? "Not Found" : "Bad Request";
    send_all(fd, "HTTP/1.1 " + std::to_string(status) + " " + reason + "\r\nContent-Length: " +
                     std::to_string(body.size()) + "\r\nConnection: close\r\n\r\n" + body);
  }

  void handle(int fd) {
    std::string buffer;
    size_t header_end;
    while ((header_end = buffer.find("\r\n\r\n")) == std::string::npos) {
      if (!read_more(fd, buffer)) return (void)::close(fd);
    }
    std::string head = buffer.substr(0, header_end);
    std::string method = head.substr(0, head.find(' '));
    size_t path_begin = method.size() + 1;
    std::string path = head.substr(path_begin, head.find(' ', path_begin) - path_begin);
    size_t length = 0;
    std::string lower = head;
    for (char& c : lower) c = char(std::tolower(static_cast<unsigned char>(c)));
    if (size_t at = lower.find("content-length:"); at != std::string::npos) {
      length = std::stoul(head.substr(at + 15));
    }
    if (lower.find("expect: 100-continue") != std::string::npos) send_all(fd, "HTTP/1.1 100 Continue\r\n\r\n");
    std::string body = buffer.substr(header_end + 4);
    while (body.size() < length && read_more(fd, body)) {
    }
    if (method == "GET") {
      ++gets_;
      std::lock_guard lock(mutex_);
      auto it = objects_.find(path);
      if (it == objects_.end()) respond(fd, 404, "");
      else respond(fd, 200, it->second);
    } else if (method == "PUT") {
      ++puts_;
      if (path.starts_with("/cas/") && sha256_(body) != path.substr(5)) {
        respond(fd, 400, "blob does not match its digest");
      } else {
        std::lock_guard lock(mutex_);
        objects_[path] = body;
        respond(fd, 200, "");
      }
    } else {
      respond(fd, 400, "");
    }
    ::close(fd);
  }

  std::function<std::string(std::string_view)> sha256_;
  int fd_ = -1;
  uint16_t port_ = 0;
  std::atomic<bool> stop_{false};
  std::atomic<int> gets_{0}, puts_{0};
  std::mutex mutex_;
  std::map<std::string, std::string> objects_;
  std::thread thread_;
};

}  // namespace facet::test_http
