// operator new as the C++ library has it, for the importer's fuzz harness.
//
// A broken model file may make Assimp ask for tens of gigabytes (a 3DS
// chunk that claims 4 billion vertices). Outside the sanitizers `new`
// throws std::bad_alloc, Assimp's ReadFile catches it and the importer
// reports the file as unreadable: the right outcome. AddressSanitizer's own
// operator new cannot throw and reports such a request as a fatal error,
// which would make every one of these files a finding. This one goes
// through malloc (which ASan still checks: overflows, use after free, leaks)
// and throws when malloc returns null (ASAN_OPTIONS
// allocator_may_return_null=1, set by scripts/fuzz.sh).
#include <cstdlib>
#include <new>

void* operator new(std::size_t size)
{
    if (void* p = std::malloc(size == 0 ? 1 : size))
        return p;
    throw std::bad_alloc();
}
void* operator new[](std::size_t size) { return operator new(size); }
void* operator new(std::size_t size, const std::nothrow_t&) noexcept { return std::malloc(size == 0 ? 1 : size); }
void* operator new[](std::size_t size, const std::nothrow_t&) noexcept { return std::malloc(size == 0 ? 1 : size); }
void* operator new(std::size_t size, std::align_val_t align)
{
    const auto a = static_cast<std::size_t>(align);
    if (void* p = std::aligned_alloc(a, (size + a - 1) / a * a))
        return p;
    throw std::bad_alloc();
}
void* operator new[](std::size_t size, std::align_val_t align) { return operator new(size, align); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
void operator delete(void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete(void* p, std::size_t, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept { std::free(p); }
