#include "engine/movie/movie_info.h"

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
}

namespace globe {

Result<MovieInfo> readMovieInfo(const std::string& file) {
  AVFormatContext* format = nullptr;
  if (avformat_open_input(&format, file.c_str(), nullptr, nullptr) < 0)
    return Error::inFile(file, "cannot open the movie");
  struct Closer {
    AVFormatContext** f;
    ~Closer() { avformat_close_input(f); }
  } closer{&format};
  if (avformat_find_stream_info(format, nullptr) < 0) return Error::inFile(file, "cannot read the movie's streams");
  int video = av_find_best_stream(format, AVMEDIA_TYPE_VIDEO, -1, -1, nullptr, 0);
  if (video < 0) return Error::inFile(file, "the movie has no video stream");
  const AVStream* stream = format->streams[video];
  MovieInfo info;
  info.width = static_cast<uint32_t>(stream->codecpar->width);
  info.height = static_cast<uint32_t>(stream->codecpar->height);
  info.codec = avcodec_get_name(stream->codecpar->codec_id);
  info.frameRate_hz = av_q2d(stream->avg_frame_rate);
  info.duration_s = stream->duration > 0 ? double(stream->duration) * av_q2d(stream->time_base) : 0.0;
  AVPacket* packet = av_packet_alloc();
  while (av_read_frame(format, packet) >= 0) {
    if (packet->stream_index == video) ++info.frames;
    av_packet_unref(packet);
  }
  av_packet_free(&packet);
  return info;
}

}  // namespace globe
