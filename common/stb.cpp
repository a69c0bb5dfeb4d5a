// stb's implementation, compiled once for the whole kit from the headers a package manager
// installed (common/dependencies.cmake finds them), so the kit links against no distribution's
// compiled stb: Homebrew and vcpkg ship only the headers.
#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_WRITE_IMPLEMENTATION
// Only PNG is read (the references and a student's picture); the other decoders stay out.
#define STBI_ONLY_PNG

#if defined(__GNUC__)
// stb is third-party code: its warnings are not the kit's to fix.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wsign-compare"
#pragma GCC diagnostic ignored "-Wunused-but-set-variable"
#endif
#if defined(_MSC_VER)
#pragma warning(push, 0)
#endif

#include <stb_image.h>
#include <stb_image_write.h>

#if defined(_MSC_VER)
#pragma warning(pop)
#endif
#if defined(__GNUC__)
#pragma GCC diagnostic pop
#endif
