// Exit status 0 when the CPU running it has AVX2 (MPMICE_SIMD auto, CMakeLists.txt).
int main() { return __builtin_cpu_supports("avx2") ? 0 : 1; }
