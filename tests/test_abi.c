/* The ABI handshake: qc_ctx_init passes the header's version and
 * sizeof(qc_ctx); a library of another ABI or size refuses the context. */
#include <string.h>

#include "quiltc.h"
#include "testalloc.h"
#include "unity.h"

static testalloc ta;

void setUp(void)
{
    memset(&ta, 0, sizeof ta);
}

void tearDown(void)
{
}

static void versions_should_agree_with_the_header(void)
{
    TEST_ASSERT_EQUAL_INT(QC_VERSION_NUMBER, qc_version_number());
    TEST_ASSERT_EQUAL_INT(QC_VERSION_MAJOR * 10000 + QC_VERSION_MINOR * 100 + QC_VERSION_PATCH,
                          qc_version_number());
    TEST_ASSERT_EQUAL_STRING(QC_VERSION_STRING, qc_version());
    TEST_ASSERT_EQUAL_STRING("EVERSION", qc_err_name(QC_EVERSION));
}

static void matching_header_should_be_accepted(void)
{
    qc_ctx ctx;
    qc_points pts = {0};
    qc_vec2 p = {1, 2};

    TEST_ASSERT_EQUAL_INT(QC_OK, qc_ctx_init(&ctx, testalloc_fn, &ta));
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_points_push(&ctx, &pts, p));
    qc_points_free(&ctx, &pts);
    TEST_ASSERT_EQUAL_size_t(0, ta.live_bytes);
    /* a patch release is the same ABI */
    TEST_ASSERT_EQUAL_INT(QC_OK, qc_ctx_init_(&ctx, NULL, NULL, QC_VERSION_NUMBER + 1, sizeof ctx));
}

/* assert_refused(version, size): the context refuses, names both versions, and
 * every later allocation fails without calling the caller's allocator. */
static void assert_refused(int version, size_t size)
{
    qc_ctx ctx;
    qc_points pts = {0};
    qc_vec2 p = {1, 2};

    TEST_ASSERT_EQUAL_INT(QC_EVERSION, qc_ctx_init_(&ctx, testalloc_fn, &ta, version, size));
    TEST_ASSERT_EQUAL_INT(QC_EVERSION, ctx.status);
    TEST_ASSERT_NOT_NULL(strstr(qc_errmsg(&ctx), QC_VERSION_STRING));
    TEST_ASSERT_NOT_NULL(strstr(qc_errmsg(&ctx), "does not match"));
    TEST_ASSERT_EQUAL_INT(QC_ENOMEM, qc_points_push(&ctx, &pts, p));
    TEST_ASSERT_NULL(pts.v);
    TEST_ASSERT_EQUAL_size_t(0, ta.allocs); /* would succeed if called */
}

static void another_major_or_pre_1_0_minor_should_be_refused(void)
{
    assert_refused(QC_VERSION_NUMBER + 10000, sizeof(qc_ctx));
    if (QC_VERSION_MAJOR == 0)
        assert_refused(QC_VERSION_NUMBER + 100, sizeof(qc_ctx));
    assert_refused(-1, sizeof(qc_ctx));
}

static void another_ctx_size_should_be_refused(void)
{
    union {
        qc_ctx ctx;
        unsigned char bytes[sizeof(qc_ctx) + 16];
    } big;
    union {
        qc_ctx ctx;
        unsigned char bytes[sizeof(qc_ctx)];
    } small;
    size_t i;

    /* larger: refused, and written only within the library's qc_ctx */
    memset(&big, 0xa5, sizeof big);
    TEST_ASSERT_EQUAL_INT(QC_EVERSION, qc_ctx_init_(&big.ctx, testalloc_fn, &ta, QC_VERSION_NUMBER,
                                                    sizeof big));
    TEST_ASSERT_NOT_NULL(strstr(qc_errmsg(&big.ctx), "bytes"));
    for (i = sizeof(qc_ctx); i < sizeof big; i++)
        TEST_ASSERT_EQUAL_HEX8(0xa5, big.bytes[i]);
    /* smaller: refused and not written at all */
    memset(&small, 0x5a, sizeof small);
    TEST_ASSERT_EQUAL_INT(QC_EVERSION, qc_ctx_init_(&small.ctx, testalloc_fn, &ta,
                                                    QC_VERSION_NUMBER, sizeof(qc_ctx) - 8));
    for (i = 0; i < sizeof small; i++)
        TEST_ASSERT_EQUAL_HEX8(0x5a, small.bytes[i]);
    assert_refused(QC_VERSION_NUMBER, sizeof(qc_ctx) + 8);
    TEST_ASSERT_EQUAL_INT(QC_EINVAL, qc_ctx_init_(NULL, NULL, NULL, QC_VERSION_NUMBER,
                                                  sizeof(qc_ctx)));
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(versions_should_agree_with_the_header);
    RUN_TEST(matching_header_should_be_accepted);
    RUN_TEST(another_major_or_pre_1_0_minor_should_be_refused);
    RUN_TEST(another_ctx_size_should_be_refused);
    return UNITY_END();
}
