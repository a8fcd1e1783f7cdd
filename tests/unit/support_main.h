/* A unit-test program's main, written once: every test file ends with
 *
 *	SUPPORT_MAIN(SUPPORT_TESTS(test_a, test_b),
 *		     SUPPORT_FIXTURE_TESTS(setup, teardown, test_c, test_d),
 *		     SUPPORT_ISA_TESTS(test_e))
 *
 * (no semicolon after it: it is a function), which runs those entries in
 * that order through support_run, so that every program takes the same
 * name filter (argv[1]) and reports its counts the same way for
 * tests/unit/run.sh.  Included by support.h. */
#ifndef RT_TESTS_SUPPORT_MAIN_H
#define RT_TESTS_SUPPORT_MAIN_H

#define SUPPORT_MAIN(...) \
	int main(int argc, char **argv) \
	{ \
		const struct CMUnitTest tests[] = { __VA_ARGS__ }; \
		return SUPPORT_RUN(tests, argc, argv); \
	}

/* SUPPORT_MAIN with group_setup(NULL) before the tests (where it answers
 * nonzero the program fails at once, nothing run) and group_teardown(NULL)
 * after them, for what the whole program shares (a temporary folder, a
 * plugin loaded).  The teardown's answer is not the program's: a folder
 * left behind is no fault of the code under test. */
#define SUPPORT_MAIN_AROUND(group_setup, group_teardown, ...) \
	int main(int argc, char **argv) \
	{ \
		const struct CMUnitTest tests[] = { __VA_ARGS__ }; \
		int rc; \
		if (group_setup(NULL) != 0) \
			return 1; \
		rc = SUPPORT_RUN(tests, argc, argv); \
		(void)group_teardown(NULL); \
		return rc; \
	}

/* cmocka_unit_test of each function named. */
#define SUPPORT_TESTS(...) SUPPORT_MAP(SUPPORT_PLAIN_, 0, 0, __VA_ARGS__)
/* cmocka_unit_test_setup_teardown of each function named, all with the
 * one fixture. */
#define SUPPORT_FIXTURE_TESTS(setup, teardown, ...) \
	SUPPORT_MAP(SUPPORT_FIXTURE_, setup, teardown, __VA_ARGS__)

/* One entry named name that runs f with *state pointing at data, for a
 * table-driven test run as several named tests (one part of the table
 * each). */
#define SUPPORT_DATA_TEST(name, f, data) { name, f, NULL, NULL, (void *)(data) }

#define SUPPORT_PLAIN_(f, setup, teardown) cmocka_unit_test(f)
#define SUPPORT_FIXTURE_(f, setup, teardown) cmocka_unit_test_setup_teardown(f, setup, teardown)

/* SUPPORT_MAP(m, a, b, x1, ..., xn) is m(x1, a, b), ..., m(xn, a, b) for
 * n up to 48 (a longer list stops the build at SUPPORT_MAP_49): the
 * preprocessor has no loop, so each length is spelled out. */
#define SUPPORT_MAP(m, a, b, ...) \
	SUPPORT_CAT(SUPPORT_MAP_, SUPPORT_COUNT(__VA_ARGS__))(m, a, b, __VA_ARGS__)
#define SUPPORT_CAT(x, y) SUPPORT_CAT_(x, y)
#define SUPPORT_CAT_(x, y) x##y
#define SUPPORT_COUNT(...) \
	SUPPORT_COUNT_(__VA_ARGS__, 49, 48, 47, 46, 45, 44, 43, 42, 41, 40, 39, 38, 37, 36, \
		       35, 34, 33, 32, 31, 30, 29, 28, 27, 26, 25, 24, 23, 22, 21, 20, 19, \
		       18, 17, 16, 15, 14, 13, 12, 11, 10, 9, 8, 7, 6, 5, 4, 3, 2, 1, 0)
#define SUPPORT_COUNT_(x1, x2, x3, x4, x5, x6, x7, x8, x9, x10, x11, x12, x13, x14, x15, \
		       x16, x17, x18, x19, x20, x21, x22, x23, x24, x25, x26, x27, x28, \
		       x29, x30, x31, x32, x33, x34, x35, x36, x37, x38, x39, x40, x41, \
		       x42, x43, x44, x45, x46, x47, x48, x49, n, ...) n
#define SUPPORT_MAP_1(m, a, b, x) m(x, a, b)
#define SUPPORT_MAP_2(m, a, b, x, ...) m(x, a, b), SUPPORT_MAP_1(m, a, b, __VA_ARGS__)
#define SUPPORT_MAP_3(m, a, b, x, ...) m(x, a, b), SUPPORT_MAP_2(m, a, b, __VA_ARGS__)
#define SUPPORT_MAP_4(m, a, b, x, ...) m(x, a, b), SUPPORT_MAP_3(m, a, b, __VA_ARGS__)
#define SUPPORT_MAP_5(m, a, b, x, ...) m(x, a, b), SUPPORT_MAP_4(m, a, b, __VA_ARGS__)
#define SUPPORT_MAP_6(m, a, b, x, ...) m(x, a, b), SUPPORT_MAP_5(m, a, b, __VA_ARGS__)
#define SUPPORT_MAP_7(m, a, b, x, ...) m(x, a, b), SUPPORT_MAP_6(m, a, b, __VA_ARGS__)
#define SUPPORT_MAP_8(m, a, b, x, ...) m(x, a, b), SUPPORT_MAP_7(m, a, b, __VA_ARGS__)
#define SUPPORT_MAP_9(m, a, b, x, ...) m(x, a, b), SUPPORT_MAP_8(m, a, b, __VA_ARGS__)
#define SUPPORT_MAP_10(m, a, b, x, ...) m(x, a, b), SUPPORT_MAP_9(m, a, b, __VA_ARGS__)
#define SUPPORT_MAP_11(m, a, b, x, ...) m(x, a, b), SUPPORT_MAP_10(m, a, b, __VA_ARGS__)
#define SUPPORT_MAP_12(m, a, b, x, ...) m(x, a, b), SUPPORT_MAP_11(m, a, b, __VA_ARGS__)
#define SUPPORT_MAP_13(m, a, b, x, ...) m(x, a, b), SUPPORT_MAP_12(m, a, b, __VA_ARGS__)
#define SUPPORT_MAP_14(m, a, b, x, ...) m(x, a, b), SUPPORT_MAP_13(m, a, b, __VA_ARGS__)
#define SUPPORT_MAP_15(m, a, b, x, ...) m(x, a, b), SUPPORT_MAP_14(m, a, b, __VA_ARGS__)
#define SUPPORT_MAP_16(m, a, b, x, ...) m(x, a, b), SUPPORT_MAP_15(m, a, b, __VA_ARGS__)
#define SUPPORT_MAP_17(m, a, b, x, ...) m(x, a, b), SUPPORT_MAP_16(m, a, b, __VA_ARGS__)
#define SUPPORT_MAP_18(m, a, b, x, ...) m(x, a, b), SUPPORT_MAP_17(m, a, b, __VA_ARGS__)
#define SUPPORT_MAP_19(m, a, b, x, ...) m(x, a, b), SUPPORT_MAP_18(m, a, b, __VA_ARGS__)
#define SUPPORT_MAP_20(m, a, b, x, ...) m(x, a, b), SUPPORT_MAP_19(m, a, b, __VA_ARGS__)
#define SUPPORT_MAP_21(m, a, b, x, ...) m(x, a, b), SUPPORT_MAP_20(m, a, b, __VA_ARGS__)
#define SUPPORT_MAP_22(m, a, b, x, ...) m(x, a, b), SUPPORT_MAP_21(m, a, b, __VA_ARGS__)
#define SUPPORT_MAP_23(m, a, b, x, ...) m(x, a, b), SUPPORT_MAP_22(m, a, b, __VA_ARGS__)
#define SUPPORT_MAP_24(m, a, b, x, ...) m(x, a, b), SUPPORT_MAP_23(m, a, b, __VA_ARGS__)
#define SUPPORT_MAP_25(m, a, b, x, ...) m(x, a, b), SUPPORT_MAP_24(m, a, b, __VA_ARGS__)
#define SUPPORT_MAP_26(m, a, b, x, ...) m(x, a, b), SUPPORT_MAP_25(m, a, b, __VA_ARGS__)
#define SUPPORT_MAP_27(m, a, b, x, ...) m(x, a, b), SUPPORT_MAP_26(m, a, b, __VA_ARGS__)
#define SUPPORT_MAP_28(m, a, b, x, ...) m(x, a, b), SUPPORT_MAP_27(m, a, b, __VA_ARGS__)
#define SUPPORT_MAP_29(m, a, b, x, ...) m(x, a, b), SUPPORT_MAP_28(m, a, b, __VA_ARGS__)
#define SUPPORT_MAP_30(m, a, b, x, ...) m(x, a, b), SUPPORT_MAP_29(m, a, b, __VA_ARGS__)
#define SUPPORT_MAP_31(m, a, b, x, ...) m(x, a, b), SUPPORT_MAP_30(m, a, b, __VA_ARGS__)
#define SUPPORT_MAP_32(m, a, b, x, ...) m(x, a, b), SUPPORT_MAP_31(m, a, b, __VA_ARGS__)
#define SUPPORT_MAP_33(m, a, b, x, ...) m(x, a, b), SUPPORT_MAP_32(m, a, b, __VA_ARGS__)
#define SUPPORT_MAP_34(m, a, b, x, ...) m(x, a, b), SUPPORT_MAP_33(m, a, b, __VA_ARGS__)
#define SUPPORT_MAP_35(m, a, b, x, ...) m(x, a, b), SUPPORT_MAP_34(m, a, b, __VA_ARGS__)
#define SUPPORT_MAP_36(m, a, b, x, ...) m(x, a, b), SUPPORT_MAP_35(m, a, b, __VA_ARGS__)
#define SUPPORT_MAP_37(m, a, b, x, ...) m(x, a, b), SUPPORT_MAP_36(m, a, b, __VA_ARGS__)
#define SUPPORT_MAP_38(m, a, b, x, ...) m(x, a, b), SUPPORT_MAP_37(m, a, b, __VA_ARGS__)
#define SUPPORT_MAP_39(m, a, b, x, ...) m(x, a, b), SUPPORT_MAP_38(m, a, b, __VA_ARGS__)
#define SUPPORT_MAP_40(m, a, b, x, ...) m(x, a, b), SUPPORT_MAP_39(m, a, b, __VA_ARGS__)
#define SUPPORT_MAP_41(m, a, b, x, ...) m(x, a, b), SUPPORT_MAP_40(m, a, b, __VA_ARGS__)
#define SUPPORT_MAP_42(m, a, b, x, ...) m(x, a, b), SUPPORT_MAP_41(m, a, b, __VA_ARGS__)
#define SUPPORT_MAP_43(m, a, b, x, ...) m(x, a, b), SUPPORT_MAP_42(m, a, b, __VA_ARGS__)
#define SUPPORT_MAP_44(m, a, b, x, ...) m(x, a, b), SUPPORT_MAP_43(m, a, b, __VA_ARGS__)
#define SUPPORT_MAP_45(m, a, b, x, ...) m(x, a, b), SUPPORT_MAP_44(m, a, b, __VA_ARGS__)
#define SUPPORT_MAP_46(m, a, b, x, ...) m(x, a, b), SUPPORT_MAP_45(m, a, b, __VA_ARGS__)
#define SUPPORT_MAP_47(m, a, b, x, ...) m(x, a, b), SUPPORT_MAP_46(m, a, b, __VA_ARGS__)
#define SUPPORT_MAP_48(m, a, b, x, ...) m(x, a, b), SUPPORT_MAP_47(m, a, b, __VA_ARGS__)

#endif
