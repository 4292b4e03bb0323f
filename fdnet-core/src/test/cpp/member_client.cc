// A C++ member of an FDNet network, on omniORB over SSLIOP (TLS): reads a Data on a host, then tries to write it, and
// prints what happened. OmniOrbMemberTest compiles it against the stubs omniidl makes from idl/fdnet.idl and runs it.
//
//   member_client IOR_FILE MODULE NODE CA_PEM KEY_PEM
//     CA_PEM   the network's CA certificate (fdnet keys writes DIR/ca.pem)
//     KEY_PEM  this member's certificate and unencrypted private key, both PEM, in one file
//
// Output: "read MODULE/NODE = VALUE", then "written" or "refused: NO_PERMISSION: REASON". Exit 0 when written,
// 3 when refused, 4 on any other failure.
//
// CORBA carries no text with a system exception; JacORB sends the reason in the reply's ExceptionDetailMessage
// service context (id 14: an encapsulated wstring), which omniORB passes to client interceptors but does not read.

#include <omniORB4/CORBA.h>
#include <omniORB4/omniInterceptors.h>
#include <omniORB4/sslContext.h>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include "fdnet.hh"

namespace {

const CORBA::ULong EXCEPTION_DETAIL_MESSAGE = 14;
std::string lastDetail;

unsigned read16(const CORBA::Octet* b, bool little) {
    return little ? (b[0] | (b[1] << 8)) : ((b[0] << 8) | b[1]);
}

unsigned long read32(const CORBA::Octet* b, bool little) {
    return little ? (b[0] | (b[1] << 8) | (b[2] << 16) | ((unsigned long) b[3] << 24))
                  : (((unsigned long) b[0] << 24) | (b[1] << 16) | (b[2] << 8) | b[3]);
}

void appendUtf8(std::string& out, unsigned c) {
    if (c < 0x80) {
        out += (char) c;
    } else if (c < 0x800) {
        out += (char) (0xC0 | (c >> 6));
        out += (char) (0x80 | (c & 0x3F));
    } else {
        out += (char) (0xE0 | (c >> 12));
        out += (char) (0x80 | ((c >> 6) & 0x3F));
        out += (char) (0x80 | (c & 0x3F));
    }
}

// The encapsulation: a byte-order octet, padding to 4, the wstring's length in octets (GIOP 1.2), UTF-16 units
// (a byte-order mark may lead them).
std::string detailText(const IOP::ServiceContext& sc) {
    const CORBA::Octet* b = sc.context_data.get_buffer();
    CORBA::ULong n = sc.context_data.length();
    if (n < 8) {
        return "";
    }
    bool little = b[0] == 1;
    unsigned long octets = read32(b + 4, little);
    std::string out;
    CORBA::ULong at = 8;
    CORBA::ULong end = (CORBA::ULong) (8 + octets < n ? 8 + octets : n);
    if (at + 2 <= end) {
        unsigned bom = read16(b + at, little);
        if (bom == 0xFEFF || bom == 0xFFFE) {
            little = bom == 0xFEFF ? little : !little;
            at += 2;
        }
    }
    for (; at + 2 <= end; at += 2) {
        unsigned c = read16(b + at, little);
        if (c != 0) {
            appendUtf8(out, c);
        }
    }
    return out;
}

CORBA::Boolean keepExceptionDetail(omni::omniInterceptors::clientReceiveReply_T::info_T& info) {
    for (CORBA::ULong i = 0; i < info.service_contexts.length(); i++) {
        if (info.service_contexts[i].context_id == EXCEPTION_DETAIL_MESSAGE) {
            lastDetail = detailText(info.service_contexts[i]);
        }
    }
    return true;
}

std::string readFile(const char* path) {
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    std::string s = text.str();
    while (!s.empty() && (s.back() == '\n' || s.back() == '\r' || s.back() == ' ')) {
        s.pop_back();
    }
    return s;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 6) {
        std::fprintf(stderr, "usage: member_client IOR_FILE MODULE NODE CA_PEM KEY_PEM\n");
        return 4;
    }
    sslContext::certificate_authority_file = argv[4];
    sslContext::key_file = argv[5];
    sslContext::key_file_password = "";
    const char* options[][2] = {{"clientTransportRule", "* ssl"}, {"giopMaxMsgSize", "10485760"}, {0, 0}};
    int orbArgc = 1;
    CORBA::ORB_var orb = CORBA::ORB_init(orbArgc, argv, "omniORB4", options);
    omni::omniInterceptors* interceptors = omniORB::getInterceptors();
    interceptors->clientReceiveReply.add(keepExceptionDetail);
    int exit = 4;
    try {
        std::string ior = readFile(argv[1]);
        CORBA::Object_var object = orb->string_to_object(ior.c_str());
        fdnet::Host_var host = fdnet::Host::_unchecked_narrow(object);
        fdnet::NodeId id;
        id.moduleName = CORBA::string_dup(argv[2]);
        id.nodeName = CORBA::string_dup(argv[3]);
        fdnet::Value_var value = host->read(id);
        std::printf("read %s/%s = %g\n", argv[2], argv[3], value->asDouble());
        std::fflush(stdout);
        fdnet::Value next;
        next.asDouble(value->asDouble() + 1.0);
        try {
            host->write(id, next);
            std::printf("written\n");
            exit = 0;
        } catch (CORBA::NO_PERMISSION&) {
            std::printf("refused: NO_PERMISSION: %s\n", lastDetail.c_str());
            exit = 3;
        }
    } catch (CORBA::SystemException& e) {
        std::printf("failed: %s (minor %lu): %s\n", e._name(), (unsigned long) e.minor(), lastDetail.c_str());
    } catch (CORBA::UserException& e) {
        std::printf("failed: %s\n", e._name());
    }
    std::fflush(stdout);
    orb->destroy();
    return exit;
}
