!> dynx-part: the ParaDyn-style preprocessor. Reads a deck (read_deck_input + build_model,
!> as bin/dynx does), partitions its element graph with METIS (dx_partition), writes one
!> HDF5 file per rank (dx_rank_file) and the partition report (stdout and DIR/partition.txt).
!> Exit codes: 0 normal, 2 input error, 4 I/O failure.
program dynx_part
   use, intrinsic :: iso_fortran_env, only: error_unit, output_unit
   use dx_error, only: error_t, EXIT_INPUT, EXIT_IO, exit_process, set_error
   use dx_strings, only: str, command_arg
   use dx_log, only: log_info
   use dx_model, only: model_t
   use dx_model_input, only: model_input_t
   use dx_deck, only: read_deck_input
   use dx_build, only: build_model
   use dx_partition, only: partition_t, rank_part_t, partition_model, rank_part, write_report, &
                           model_conn
   use dx_rank_file, only: write_rank_file, read_rank_file, rank_file_name, deck_content_hash
   use dx_io_sys, only: sys_mkdir_p
   use dx_par_contact, only: contact_groups, write_contact_report
   use dx_par_model, only: par_model_verify
   implicit none
   character(:), allocatable :: deck, outdir, arg, val
   type(model_input_t) :: inp
   type(model_t) :: model
   type(partition_t) :: part
   type(rank_part_t) :: rp
   type(error_t), allocatable :: error
   character(16) :: hash
   logical :: ignore_unknown, verify
   integer :: i, n, np, ios, r, u
   integer, allocatable :: grp_ptr(:), grp_elem(:), gid(:)

   np = 0
   outdir = '.'
   deck = ''
   ignore_unknown = .false.
   verify = .false.
   n = command_argument_count()
   i = 1
   do while (i <= n)
      arg = command_arg(i)
      select case (arg)
      case ('-h', '--help')
         call usage(); stop
      case ('-n', '--nprocs')
         val = option_value(i)
         read(val, *, iostat=ios) np
         if (ios /= 0 .or. np < 1) call die_usage('-n needs a positive integer, got '//val)
      case ('-o', '--outdir')
         outdir = option_value(i)
      case ('--ignore-unknown')
         ignore_unknown = .true.
      case ('--verify')
         verify = .true.
      case default
         if (arg(1:1) == '-' .or. len(deck) > 0) call die_usage('unknown argument '//arg)
         deck = arg
      end select
      i = i + 1
   end do
   if (len(deck) == 0) call die_usage('no input deck: dynx-part deck.k -n NP [-o DIR]')
   if (np < 1) call die_usage('no number of ranks: dynx-part deck.k -n NP [-o DIR]')

   call read_deck_input(deck, inp, error, ignore_unknown)
   if (allocated(error)) call die(error)
   model%deck_file = deck
   call build_model(inp, model, error)       ! as bin/dynx: model, contact pairs, emc
   if (allocated(error)) call die(error)
   call deck_content_hash(inp%files, hash, error)
   if (allocated(error)) call die(error)
   if (verify) then
      call verify_files(error)
      if (allocated(error)) call die(error)
      stop
   end if
   ! element groups that must stay on one rank: one per local contact pair of the deck
   ! (dx_par_contact: the elements with a face on either surface)
   call contact_groups(model, grp_ptr, grp_elem, gid)
   call partition_model(model, np, grp_ptr, grp_elem, part, error)
   if (allocated(error)) call die(error)

   call sys_mkdir_p(outdir, error)
   if (allocated(error)) call die(error)
   do r = 0, np - 1
      call rank_part(model, part, r, rp, error)
      if (allocated(error)) call die(error)
      call write_rank_file(rank_file_name(outdir, r), rp, hash, error)
      if (allocated(error)) call die(error)
   end do
   call write_report(output_unit, part, deck, hash)
   call write_contact_report(output_unit, part, grp_ptr, grp_elem, gid)
   open(newunit=u, file=outdir//'/partition.txt', status='replace', action='write', iostat=ios)
   if (ios /= 0) then
      call set_error(error, 'cannot write '//outdir//'/partition.txt', EXIT_IO)
      call die(error)
   end if
   call write_report(u, part, deck, hash)
   call write_contact_report(u, part, grp_ptr, grp_elem, gid)
   close(u)
   call log_info('dynx-part: wrote '//str(np)//' rank files '//rank_file_name(outdir, 0)// &
                 ' ... and '//outdir//'/partition.txt')

contains

   !> --verify: read every rank file of DIR for this deck and NP (each is checked for its
   !> checksum, deck hash, NP and rank) and check them together: every element on exactly
   !> one rank, each rank holding the nodes of its elements, symmetric shared-node lists.
   subroutine verify_files(error)
      type(error_t), allocatable, intent(out) :: error
      type(rank_part_t), allocatable :: rps(:)
      integer, allocatable :: seen(:), conn(:, :), holder(:, :)
      integer :: r, k, q, kq, e, ib, j, nsh
      character(:), allocatable :: msg
      allocate(rps(0:np - 1), seen(model%ne))
      call model_conn(model, conn)
      seen = 0
      do r = 0, np - 1
         call read_rank_file(rank_file_name(outdir, r), hash, np, r, rps(r), error)
         if (allocated(error)) return
         if (rps(r)%ne_global /= model%ne .or. rps(r)%nn_global /= model%nn) then
            call set_error(error, rank_file_name(outdir, r)//': element or node count '// &
                           'differs from the deck', EXIT_INPUT)
            return
         end if
         call par_model_verify(model, rps(r), msg)   ! the file's sub-model = the cut
         if (len(msg) > 0) then
            call set_error(error, rank_file_name(outdir, r)//': the sub-model built from '// &
               'the file differs from the one cut from the deck''s model: '//msg, EXIT_INPUT)
            return
         end if
         do k = 1, size(rps(r)%elements)
            e = rps(r)%elements(k)
            seen(e) = seen(e) + 1
            if (k > 1) then
               if (e <= rps(r)%elements(k - 1)) then
                  call set_error(error, rank_file_name(outdir, r)//': elements not in '// &
                                 'ascending global order', EXIT_INPUT)
                  return
               end if
            end if
         end do
      end do
      if (any(seen /= 1)) then
         call set_error(error, outdir//': '//str(count(seen == 0))//' elements on no rank, '// &
            str(count(seen > 1))//' on more than one', EXIT_INPUT)
         return
      end if
      ! holder(n, r): node n is in rank r's node list
      allocate(holder(model%nn, 0:np - 1))
      holder = 0
      do r = 0, np - 1
         holder(rps(r)%nodes, r) = 1
         do k = 1, size(rps(r)%elements)
            if (any(holder(conn(:, rps(r)%elements(k)), r) == 0)) then
               call set_error(error, rank_file_name(outdir, r)//': element '// &
                  str(model%elem_label(rps(r)%elements(k)))//' has a node missing from '// &
                  'the rank''s node list', EXIT_INPUT)
               return
            end if
         end do
      end do
      nsh = 0
      do r = 0, np - 1
         do k = 1, size(rps(r)%nbr)
            q = rps(r)%nbr(k)
            kq = findloc(rps(q)%nbr, r, dim=1)
            associate (a => rps(r)%nbr_nodes(rps(r)%nbr_ptr(k):rps(r)%nbr_ptr(k + 1) - 1))
               if (kq == 0) then
                  call set_error(error, rank_file_name(outdir, r)//': shares nodes with rank '// &
                     str(q)//', which does not list rank '//str(r), EXIT_INPUT)
                  return
               end if
               associate (b => rps(q)%nbr_nodes(rps(q)%nbr_ptr(kq):rps(q)%nbr_ptr(kq + 1) - 1))
                  if (size(a) /= size(b)) then
                     call set_error(error, 'shared-node lists of ranks '//str(r)//' and '// &
                                    str(q)//' differ in length', EXIT_INPUT)
                     return
                  end if
                  if (any(a /= b)) then
                     call set_error(error, 'shared-node lists of ranks '//str(r)//' and '// &
                                    str(q)//' differ', EXIT_INPUT)
                     return
                  end if
               end associate
               do j = 1, size(a)
                  if (holder(a(j), q) == 0) then
                     call set_error(error, 'rank '//str(r)//' lists node '// &
                        str(model%node_label(a(j)))//' as shared with rank '//str(q)// &
                        ', which does not hold it', EXIT_INPUT)
                     return
                  end if
               end do
               nsh = nsh + size(a)
            end associate
         end do
      end do
      call log_info('dynx-part: verified '//str(np)//' rank files in '//outdir//': every '// &
         'element on exactly one rank, shared-node lists symmetric ('//str(nsh/2)// &
         ' node-rank pairs), each rank''s sub-model from its file equal to the cut from '// &
         'the deck bit for bit')
   end subroutine verify_files

   subroutine usage()
      write(output_unit, '(a)') &
         'usage: dynx-part deck.k -n NP [-o DIR] [--ignore-unknown] [--verify]', &
         '', &
         'Partitions the deck''s elements into NP ranks with METIS and writes', &
         '  DIR/rank_00000.h5 ... one HDF5 file per rank (elements, nodes, shared nodes,', &
         '                        boundary conditions and loads on its nodes, and its', &
         '                        sub-model: node coordinates, velocities, labels, element', &
         '                        pieces of the serial blocks with their connectivity)', &
         '  DIR/partition.txt     the partition report (also printed)', &
         '', &
         'options:', &
         '  -n, --nprocs NP      number of ranks (required)', &
         '  -o, --outdir DIR     output directory (default: current directory)', &
         '  --ignore-unknown     unknown keywords are warnings, not errors', &
         '  --verify             write nothing: read DIR''s rank files back and check them', &
         '                       against the deck (checksum, deck hash, NP, every element', &
         '                       on exactly one rank, symmetric shared-node lists, the', &
         '                       sub-model built from each file equal to the cut from the', &
         '                       deck bit for bit)', &
         '  -h, --help           this text', &
         '', &
         'exit codes: 0 normal, 2 input error, 4 I/O failure'
   end subroutine usage

   subroutine die_usage(msg)
      character(*), intent(in) :: msg
      write(error_unit, '(a)') 'dynx-part: error: '//msg
      write(error_unit, '(a)') 'dynx-part: try dynx-part --help'
      call exit_process(EXIT_INPUT)
   end subroutine die_usage

   subroutine die(err)
      type(error_t), intent(in) :: err
      write(error_unit, '(a)') 'dynx-part: error: '//err%message
      call exit_process(err%code)
   end subroutine die

   !> The value of the option at i: the next argument (i moves to it); none is a usage error.
   function option_value(i) result(a)
      integer, intent(inout) :: i
      character(:), allocatable :: a
      i = i + 1
      if (i > command_argument_count()) call die_usage('missing value after the last option')
      a = command_arg(i)
   end function option_value
end program dynx_part
