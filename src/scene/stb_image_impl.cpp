// The single translation unit that holds stb_image's implementation; every
// other file includes the header for declarations only.
#define STB_IMAGE_IMPLEMENTATION
#define STBI_FAILURE_USERMSG
#include <stb/stb_image.h>
