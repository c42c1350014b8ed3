// SPDX-FileCopyrightText: 2026 Robogene contributors
// SPDX-License-Identifier: BSD-3-Clause
//
// One-way streaming of 640x480 RGB images between two ports over the shmem carrier, against the
// tcp carrier (the baseline) for the same frames in the same run; both wait for each frame's ack.
// Also a large frame (1920x1080 RGB, 6.2 MB) where the copy through the kernel costs most.
// Usage: bench_shmem [--frames=1000]
#include <algorithm>
#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <thread>
#include <vector>

#include "bench_common.hpp"
#include "robogene/port.hpp"

using namespace robogene;

namespace {

Bottle make_image(const std::vector<std::uint8_t>& pixels, int w, int h) {
  Bottle img;
  img.add(Value::vocab("mat"));
  img.add(Value::vocab("rgb"));
  img.add(Value::list(Bottle{3, static_cast<int>(pixels.size()), 65544, w, h}));
  img.add(Value::blob(pixels.data(), pixels.size()));
  return img;
}

double mb_per_s(int frames, const char* carrier, const Bottle& img) {
  Port r, w;
  r.open_at("/bench/image:i", {"127.0.0.1", 0});
  w.open_at("/bench/image:o", {"127.0.0.1", 0});
  const std::size_t pixels = img.get(3).as_blob().size();
  std::atomic<int> got{0};
  std::atomic<std::size_t> bytes{0};
  r.set_reader([&](const Bottle& b, const MessageInfo&, Bottle*) {
    bytes += b.get(3).as_blob().size();
    ++got;
  });
  Contact to = r.contact();
  to.carrier = carrier;
  w.add_output(to);
  auto start = bench::Clock::now();
  for (int i = 0; i < frames; ++i) w.write(img);
  while (got < frames) std::this_thread::yield();
  double secs = bench::micros(bench::Clock::now() - start) / 1e6;
  if (bytes != static_cast<std::size_t>(frames) * pixels) {
    std::fprintf(stderr, "%s: received %zu pixel bytes, expected %zu\n", carrier, bytes.load(),
                 static_cast<std::size_t>(frames) * pixels);
    std::exit(1);
  }
  return frames * static_cast<double>(img.encoded_size()) / secs / 1e6;
}

}  // namespace

int main(int argc, char** argv) {
  int frames = bench::arg_int(argc, argv, "frames", 1000);
  std::vector<std::uint8_t> vga(640 * 480 * 3), hd(1920 * 1080 * 3);
  for (std::size_t i = 0; i < vga.size(); ++i) vga[i] = static_cast<std::uint8_t>(i);
  for (std::size_t i = 0; i < hd.size(); ++i) hd[i] = static_cast<std::uint8_t>(i * 7);
  Bottle small = make_image(vga, 640, 480), big = make_image(hd, 1920, 1080);
  const int big_frames = std::max(1, frames / 6);
  // The machine is shared: every variant three times, interleaved, each one's best kept.
  double tcp = 0, shm = 0, tcp_hd = 0, shm_hd = 0;
  for (int round = 0; round < 3; ++round) {
    tcp = std::max(tcp, mb_per_s(frames, "tcp", small));
    shm = std::max(shm, mb_per_s(frames, "shmem", small));
    tcp_hd = std::max(tcp_hd, mb_per_s(big_frames, "tcp", big));
    shm_hd = std::max(shm_hd, mb_per_s(big_frames, "shmem", big));
  }
  std::printf("image stream over shmem vs tcp, best of 3 (MB/s, frames/s)\n");
  std::printf("  640x480,   %5d frames: tcp   %6.0f %6.0f\n", frames, tcp, tcp * 1e6 / small.encoded_size());
  std::printf("                          shmem %6.0f %6.0f   %.2fx tcp\n", shm, shm * 1e6 / small.encoded_size(), shm / tcp);
  std::printf("  1920x1080, %5d frames: tcp   %6.0f %6.0f\n", big_frames, tcp_hd, tcp_hd * 1e6 / big.encoded_size());
  std::printf("                          shmem %6.0f %6.0f   %.2fx tcp\n", shm_hd, shm_hd * 1e6 / big.encoded_size(), shm_hd / tcp_hd);
  std::printf("RESULT shmem_vs_tcp_vga=%.2f shmem_vs_tcp_1080p=%.2f\n", shm / tcp, shm_hd / tcp_hd);
  return 0;
}
