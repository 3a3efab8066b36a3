#include "decomposition/Communicator.H"

#include <stdexcept>

namespace suspension
{

namespace
{
    class SerialCommunicator final : public Communicator
    {
    public:

        int rank() const override { return 0; }

        int size() const override { return 1; }

        void sum(double*, std::size_t) const override {}

        void max(double*, std::size_t) const override {}

        void exchange
        (
            const std::vector<Buffer>& send,
            std::vector<Buffer>& receive
        ) const override
        {
            if (send.size() != 1)
            {
                throw std::invalid_argument
                (
                    "Communicator::exchange: one buffer per process expected"
                );
            }
            receive = send;
        }
    };
}


const Communicator& serialCommunicator()
{
    static const SerialCommunicator serial;
    return serial;
}

} // namespace suspension
