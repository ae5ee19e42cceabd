// Whole-buffer reads and writes on file descriptors, retried on EINTR and short counts: what the
// build's worker pool, Bazel's persistent worker and the conversion service each send over pipes
// and sockets.
#pragma once

#include <cstddef>

namespace stereoshift {

// write(2) until all `size` bytes are written; false on an error or a closed pipe.
bool writeAll(int fd, const void* data, size_t size);
// To a socket: send(2) with MSG_NOSIGNAL, so a peer that went away (a server killed, a client given
// up) is an error to handle, never a SIGPIPE that ends this process.
bool sendAll(int fd, const void* data, size_t size);
// read(2) until exactly `size` bytes are read; false on an error or end of file before that.
bool readAll(int fd, void* data, size_t size);

}  // namespace stereoshift
