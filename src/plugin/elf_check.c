/* The checks of a plugin file's bytes before dlopen maps it: the ELF
 * header (magic, class, byte order, a shared object, the processor), and
 * every program header's segment and the section header table within the
 * file.  dlopen trusts them: a truncated .so (an interrupted copy) maps
 * pages past the end of the file and dies of SIGBUS when they are
 * touched, and a .so of another processor fails with a misleading
 * "No such file or directory" or "wrong ELF class". */
#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "plugin/loader.h"

#if defined(__ELF__)
#include <elf.h>

#if UINTPTR_MAX > 0xffffffffu
#define ELF_CLASS_HOST ELFCLASS64
typedef Elf64_Ehdr elf_ehdr;
typedef Elf64_Phdr elf_phdr;
typedef Elf64_Shdr elf_shdr;
#else
#define ELF_CLASS_HOST ELFCLASS32
typedef Elf32_Ehdr elf_ehdr;
typedef Elf32_Phdr elf_phdr;
typedef Elf32_Shdr elf_shdr;
#endif

/* The processors a plugin may name, for the messages. */
static const struct {
	unsigned machine;
	const char *name;
} elf_machines[] = {
	{ EM_386, "i386" },	    { EM_X86_64, "x86-64" }, { EM_ARM, "arm" },
	{ EM_AARCH64, "aarch64" }, { EM_PPC, "ppc" },	     { EM_PPC64, "ppc64" },
	{ EM_S390, "s390x" },	    { EM_MIPS, "mips" },     { EM_SPARCV9, "sparc64" },
#ifdef EM_RISCV
	{ EM_RISCV, "riscv" },
#endif
#ifdef EM_LOONGARCH
	{ EM_LOONGARCH, "loongarch" },
#endif
};

/* The host's processor, as its compiler says it (0: not known here, not
 * checked). */
static unsigned elf_machine_host(void)
{
#if defined(__x86_64__)
	return EM_X86_64;
#elif defined(__i386__)
	return EM_386;
#elif defined(__aarch64__)
	return EM_AARCH64;
#elif defined(__arm__)
	return EM_ARM;
#elif defined(__powerpc64__)
	return EM_PPC64;
#elif defined(__powerpc__)
	return EM_PPC;
#elif defined(__s390x__)
	return EM_S390;
#elif defined(__riscv) && defined(EM_RISCV)
	return EM_RISCV;
#else
	return 0;
#endif
}

static void elf_machine_name(unsigned machine, char *buf, size_t size)
{
	size_t i;

	for (i = 0; i < sizeof(elf_machines) / sizeof(elf_machines[0]); i++)
		if (elf_machines[i].machine == machine) {
			snprintf(buf, size, "%s", elf_machines[i].name);
			return;
		}
	snprintf(buf, size, "ELF machine %u", machine);
}

/* Whether [off, off + n * size) lies within len bytes (no overflow). */
static bool elf_within(uint64_t off, uint64_t n, uint64_t size, size_t len)
{
	return off <= len && (size == 0 || n <= (len - off) / size);
}

int plugin_elf_check(const char *path, const unsigned char *bytes, size_t len, struct diag *d)
{
	static const uint16_t one = 1;
	const bool little = *(const unsigned char *)&one == 1;
	unsigned host = elf_machine_host();
	char want[32], found[32];
	elf_ehdr eh;
	size_t i;

	if (len < EI_NIDENT || memcmp(bytes, ELFMAG, SELFMAG) != 0)
		return diag_fail(d, RT_E_SYNTAX,
				 "plugin %s: not a plugin: invalid ELF header (not a shared object)",
				 path);
	if (bytes[EI_CLASS] != ELF_CLASS_HOST)
		return diag_fail(d, RT_E_SYNTAX, "plugin %s: not a plugin for this whitted: a %d-bit "
				 "shared object, this whitted is %d-bit", path,
				 bytes[EI_CLASS] == ELFCLASS64 ? 64 : 32,
				 ELF_CLASS_HOST == ELFCLASS64 ? 64 : 32);
	if (bytes[EI_DATA] != (little ? ELFDATA2LSB : ELFDATA2MSB))
		return diag_fail(d, RT_E_SYNTAX, "plugin %s: not a plugin for this whitted: its byte "
				 "order is %s-endian, this processor's is %s-endian", path,
				 little ? "big" : "little", little ? "little" : "big");
	if (len < sizeof(eh))
		return diag_fail(d, RT_E_SYNTAX, "plugin %s: not a plugin: the file is cut short "
				 "(%zu bytes, less than its ELF header): an interrupted copy?", path, len);
	memcpy(&eh, bytes, sizeof(eh));
	if (host && eh.e_machine != host) {
		elf_machine_name(eh.e_machine, found, sizeof(found));
		elf_machine_name(host, want, sizeof(want));
		return diag_fail(d, RT_E_SYNTAX, "plugin %s: built for %s, this is %s (rebuild it "
				 "on this machine)", path, found, want);
	}
	if (eh.e_type != ET_DYN)
		return diag_fail(d, RT_E_SYNTAX, "plugin %s: not a plugin: an ELF file but not a "
				 "shared object (build it with -shared -fPIC)", path);
	if (eh.e_phnum == 0 || eh.e_phentsize != sizeof(elf_phdr) ||
	    !elf_within(eh.e_phoff, eh.e_phnum, sizeof(elf_phdr), len))
		return diag_fail(d, RT_E_SYNTAX, "plugin %s: not a plugin: its program headers lie "
				 "outside the file (%zu bytes): cut short, or damaged", path, len);
	for (i = 0; i < eh.e_phnum; i++) {
		elf_phdr ph;

		memcpy(&ph, bytes + eh.e_phoff + i * sizeof(ph), sizeof(ph));
		if ((ph.p_type == PT_LOAD || ph.p_type == PT_DYNAMIC) &&
		    !elf_within(ph.p_offset, 1, ph.p_filesz, len))
			return diag_fail(d, RT_E_SYNTAX, "plugin %s: not a plugin: the file is cut "
					 "short (a segment reaches byte %llu, the file has %zu): an "
					 "interrupted copy?", path,
					 (unsigned long long)ph.p_offset + (unsigned long long)ph.p_filesz,
					 len);
	}
	if (eh.e_shnum != 0 && (eh.e_shentsize != sizeof(elf_shdr) ||
				!elf_within(eh.e_shoff, eh.e_shnum, sizeof(elf_shdr), len)))
		return diag_fail(d, RT_E_SYNTAX, "plugin %s: not a plugin: its section headers lie "
				 "outside the file (%zu bytes): cut short, or damaged", path, len);
	return 0;
}

#else

int plugin_elf_check(const char *path, const unsigned char *bytes, size_t len, struct diag *d)
{
	(void)path, (void)bytes, (void)len, (void)d;
	return 0;
}

#endif
