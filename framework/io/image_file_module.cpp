// The image-file module: OpenImageIO behind the two functions of raster.h. Built as a shared
// library of its own and loaded by raster_files.cpp on first use.
#include <OpenImageIO/imageio.h>

#include "io/raster.h"

using pathway::Raster;
using pathway::RasterHeader;

extern "C" bool pathwayWriteRaster(const char* path, const RasterHeader& header, bool eightBit,
                                   const void* pixels, std::string& error) {
  const OIIO::TypeDesc type = eightBit ? OIIO::TypeDesc::UINT8 : OIIO::TypeDesc::FLOAT;
  OIIO::ImageSpec spec(header.width, header.height, static_cast<int>(header.channels.size()), type);
  spec.channelnames = header.channels;
  for (const auto& [key, value] : header.attributes) spec.attribute(key, value);
  auto out = OIIO::ImageOutput::create(path);
  if (!out) {
    error = "cannot write this image format: " + OIIO::geterror();
    return false;
  }
  if (!(out->open(path, spec) && out->write_image(type, pixels) && out->close())) {
    error = out->geterror();
    return false;
  }
  return true;
}

extern "C" bool pathwayReadRaster(const char* path, Raster& raster, std::string& error) {
  auto in = OIIO::ImageInput::open(path);
  if (!in) {
    error = OIIO::geterror();
    return false;
  }
  const OIIO::ImageSpec& spec = in->spec();
  RasterHeader& header = raster.header;
  header.width = spec.width;
  header.height = spec.height;
  header.channels = spec.channelnames;
  raster.pixels.resize(static_cast<size_t>(spec.width) * spec.height * spec.nchannels);
  if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, raster.pixels.data())) {
    error = in->geterror();
    return false;
  }
  for (const OIIO::ParamValue& param : spec.extra_attribs)
    if (param.type() == OIIO::TypeDesc::STRING)
      header.attributes.emplace_back(param.name().string(), param.get_string());
  in->close();
  return true;
}
