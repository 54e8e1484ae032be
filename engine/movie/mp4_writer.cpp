#include "engine/movie/mp4_writer.h"

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/imgutils.h>
#include <libavutil/log.h>
#include <libavutil/opt.h>
#include <libswscale/swscale.h>
}

#include <fmt/format.h>

#include <vector>

namespace globe {

namespace {
std::string avError(int code) {
  char text[AV_ERROR_MAX_STRING_SIZE] = {};
  av_strerror(code, text, sizeof(text));
  return text;
}

// The best encoder libavcodec has: libx264, other H.264 encoders, then MPEG-4 part 2.
const AVCodec* chooseEncoder() {
  for (const char* name : {"libx264", "libopenh264", "h264_v4l2m2m"})
    if (const AVCodec* c = avcodec_find_encoder_by_name(name)) return c;
  if (const AVCodec* c = avcodec_find_encoder(AV_CODEC_ID_H264)) return c;
  return avcodec_find_encoder(AV_CODEC_ID_MPEG4);
}
}  // namespace

struct Mp4Writer::Impl {
  std::string file;
  std::string description;
  AVFormatContext* format = nullptr;
  AVCodecContext* codec = nullptr;
  AVStream* stream = nullptr;
  SwsContext* scale = nullptr;
  AVFrame* frame = nullptr;
  AVPacket* packet = nullptr;
  int64_t nextPts = 0;

  ~Impl() {
    if (format && format->pb) avio_closep(&format->pb);
    av_packet_free(&packet);
    av_frame_free(&frame);
    sws_freeContext(scale);
    avcodec_free_context(&codec);
    avformat_free_context(format);
  }

  Error error(const std::string& what, int code) const {
    return Error::inFile(file, fmt::format("{}: {}", what, avError(code)));
  }

  // Sends `input` (nullptr flushes) and writes every packet the encoder has ready.
  Status encode(AVFrame* input) {
    if (int r = avcodec_send_frame(codec, input); r < 0) return error("cannot encode a frame", r);
    for (;;) {
      int r = avcodec_receive_packet(codec, packet);
      if (r == AVERROR(EAGAIN) || r == AVERROR_EOF) return Ok{};
      if (r < 0) return error("cannot encode a frame", r);
      av_packet_rescale_ts(packet, codec->time_base, stream->time_base);
      packet->stream_index = stream->index;
      if (int w = av_interleaved_write_frame(format, packet); w < 0) return error("cannot write a frame", w);
    }
  }

  Status openCodec(const AVCodec* encoder, uint32_t width, uint32_t height, int fps) {
    codec = avcodec_alloc_context3(encoder);
    codec->width = static_cast<int>(width);
    codec->height = static_cast<int>(height);
    codec->time_base = AVRational{1, fps};
    codec->framerate = AVRational{fps, 1};
    codec->pix_fmt = AV_PIX_FMT_YUV420P;
    codec->gop_size = fps;  // a key frame every second, for seeking
    codec->thread_count = 1;
    codec->flags |= AV_CODEC_FLAG_BITEXACT;
    if (format->oformat->flags & AVFMT_GLOBALHEADER) codec->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
    if (std::string(encoder->name) == "libx264") {
      av_opt_set(codec->priv_data, "preset", "medium", 0);
      av_opt_set(codec->priv_data, "crf", "18", 0);  // visually lossless for rendered terrain
      // x264 0.164's AVX-512 macroblock-tree code reads uninitialised heap: the same frames gave
      // a different file per run (issue 40 item 10; MALLOC_PERTURB_ values change the output,
      // asm=avx2 or no-mbtree make it constant). AVX2 is a subset of AVX-512, so this only
      // narrows the instruction set where the defect is.
      if (__builtin_cpu_supports("avx512f")) av_opt_set(codec->priv_data, "x264-params", "asm=avx2", 0);
    } else {
      codec->bit_rate = int64_t(width) * height * fps / 4;  // ~0.25 bit per pixel and frame
    }
    if (int r = avcodec_open2(codec, encoder, nullptr); r < 0) return error("cannot open the encoder", r);
    stream = avformat_new_stream(format, nullptr);
    stream->time_base = codec->time_base;
    stream->avg_frame_rate = codec->framerate;
    if (int r = avcodec_parameters_from_context(stream->codecpar, codec); r < 0)
      return error("cannot configure the stream", r);
    return Ok{};
  }
};

Mp4Writer::Mp4Writer(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
Mp4Writer::~Mp4Writer() = default;

const std::string& Mp4Writer::encoderDescription() const { return impl_->description; }

Result<std::unique_ptr<Mp4Writer>> Mp4Writer::open(const std::string& file, uint32_t width, uint32_t height, int fps) {
  if (width % 2 || height % 2)
    return Error::inFile(file, fmt::format("MP4 frames need an even width and height, got {}x{}", width, height));
  av_log_set_level(AV_LOG_ERROR);  // the encoder's statistics are noise on a command line
  auto impl = std::make_unique<Impl>();
  impl->file = file;
  if (int r = avformat_alloc_output_context2(&impl->format, nullptr, "mp4", file.c_str()); r < 0)
    return impl->error("cannot create an MP4 file", r);
  impl->format->flags |= AVFMT_FLAG_BITEXACT;  // no library version strings or times in the file
  const AVCodec* encoder = chooseEncoder();
  if (!encoder) return Error::inFile(file, "libavcodec has no H.264 or MPEG-4 encoder");
  impl->description = fmt::format("{} ({})", encoder->name, encoder->long_name ? encoder->long_name : "");
  if (Status s = impl->openCodec(encoder, width, height, fps); !s) return s.error();
  if (int r = avio_open(&impl->format->pb, file.c_str(), AVIO_FLAG_WRITE); r < 0)
    return impl->error("cannot open for writing", r);
  if (int r = avformat_write_header(impl->format, nullptr); r < 0) return impl->error("cannot write the header", r);
  impl->frame = av_frame_alloc();
  impl->frame->format = AV_PIX_FMT_YUV420P;
  impl->frame->width = static_cast<int>(width);
  impl->frame->height = static_cast<int>(height);
  if (int r = av_frame_get_buffer(impl->frame, 0); r < 0) return impl->error("cannot allocate a frame", r);
  impl->packet = av_packet_alloc();
  impl->scale = sws_getContext(static_cast<int>(width), static_cast<int>(height), AV_PIX_FMT_RGB24,
                               static_cast<int>(width), static_cast<int>(height), AV_PIX_FMT_YUV420P,
                               SWS_BICUBIC | SWS_ACCURATE_RND | SWS_BITEXACT, nullptr, nullptr, nullptr);
  return std::unique_ptr<Mp4Writer>(new Mp4Writer(std::move(impl)));
}

Status Mp4Writer::addFrame(const ImageRgba& image) {
  Impl& m = *impl_;
  if (int(image.width) != m.codec->width || int(image.height) != m.codec->height)
    return Error::inFile(m.file, fmt::format("frame is {}x{}, the movie {}x{}", image.width, image.height,
                                             m.codec->width, m.codec->height));
  std::vector<uint8_t> rgb(std::size_t(image.width) * image.height * 3);
  for (std::size_t p = 0; p < std::size_t(image.width) * image.height; ++p)
    for (std::size_t c = 0; c < 3; ++c) rgb[p * 3 + c] = linearToSrgb8(image.rgba[p * 4 + c]);
  if (int r = av_frame_make_writable(m.frame); r < 0) return m.error("cannot write a frame", r);
  const uint8_t* src[1] = {rgb.data()};
  const int srcStride[1] = {static_cast<int>(image.width * 3)};
  sws_scale(m.scale, src, srcStride, 0, static_cast<int>(image.height), m.frame->data, m.frame->linesize);
  m.frame->pts = m.nextPts++;
  return m.encode(m.frame);
}

Status Mp4Writer::finish() {
  Impl& m = *impl_;
  if (Status s = m.encode(nullptr); !s) return s;
  if (int r = av_write_trailer(m.format); r < 0) return m.error("cannot finish the MP4 file", r);
  if (int r = avio_closep(&m.format->pb); r < 0) return m.error("cannot close", r);
  return Ok{};
}

}  // namespace globe
